#include "apcs/lesson/handout_index.h"

#include <catch2/catch.hpp>

#include <string>
#include <vector>

using namespace apcs;

namespace {

std::size_t count_of(const std::string& text, const std::string& part)
{
    std::size_t count = 0;
    for (std::size_t at = text.find(part); at != std::string::npos; at = text.find(part, at + part.size()))
        ++count;
    return count;
}

} // namespace

TEST_CASE("HTML escaping turns & < > \" ' into references and keeps UTF-8 as it is", "[handout]")
{
    REQUIRE(html_escaped("a < b && c > \"d\" 'e'") == "a &lt; b &amp;&amp; c &gt; &quot;d&quot; &#39;e&#39;");
    REQUIRE(html_escaped("\u0E2A\u0E27\u0E31\u0E2A\u0E14\u0E35 → 1989") == "\u0E2A\u0E27\u0E31\u0E2A\u0E14\u0E35 → 1989");
    REQUIRE(html_escaped("&amp;") == "&amp;amp;");
    REQUIRE(html_escaped("").empty());
}

TEST_CASE("a caption's bytes that are not UTF-8 reach the index as U+FFFD, as they reach the .txt page", "[handout][names]")
{
    REQUIRE(html_escaped("bad \xFF\xC3 end") == "bad \uFFFD\uFFFD end");
    const std::string html = handout_index_html("t", {HandoutPage{1, "01-x.png", "tension \xE9t\xE9"}});
    REQUIRE(html.find("tension \uFFFDt\uFFFD") != std::string::npos);
    REQUIRE(html.find('\xE9') == std::string::npos);
}

TEST_CASE("a handout's index holds each page's picture and escaped caption in order", "[handout]")
{
    const std::vector<HandoutPage> pages = {
        {2, "02-w-opens.png", "W opens the editor"},
        {4, "04-t-shows.png", "T shows <DS> & \"DD\""},
        {10, "10-summary.png", "Überblick: สวัสดี"},
    };
    const std::string html = handout_index_html("lesson <1>.keys", pages);
    REQUIRE(html.starts_with("<!DOCTYPE html>\n<html>\n<head>\n<meta charset=\"utf-8\">\n<title>lesson &lt;1&gt;.keys</title>"));
    REQUIRE(count_of(html, "<figure>") == 3);
    REQUIRE(count_of(html, "<img ") == 3);
    const std::size_t first = html.find("<img src=\"02-w-opens.png\" alt=\"W opens the editor\">\n<figcaption>2. W opens the editor</figcaption>");
    const std::size_t second = html.find("<img src=\"04-t-shows.png\" alt=\"T shows &lt;DS&gt; &amp; &quot;DD&quot;\">\n"
                                         "<figcaption>4. T shows &lt;DS&gt; &amp; &quot;DD&quot;</figcaption>");
    const std::size_t third = html.find("<figcaption>10. Überblick: สวัสดี</figcaption>");
    REQUIRE(first != std::string::npos);
    REQUIRE(second != std::string::npos);
    REQUIRE(third != std::string::npos);
    REQUIRE(first < second);
    REQUIRE(second < third);
    // Nothing of the captions' markup is left raw, and nothing is fetched from elsewhere.
    REQUIRE(html.find("<DS>") == std::string::npos);
    REQUIRE(html.find("http") == std::string::npos);
    REQUIRE(html.find("<script") == std::string::npos);
}

TEST_CASE("a handout's index prints two pictures a sheet and keeps each with its caption", "[handout]")
{
    const std::string html = handout_index_html("lesson.keys", {{1, "01-a.png", "a"}});
    // A page break after every second figure, none after the last; a figure never split.
    REQUIRE(html.find("figure:nth-of-type(2n) { break-after: page; page-break-after: always; }") != std::string::npos);
    REQUIRE(html.find("figure:last-of-type { break-after: auto; page-break-after: auto; }") != std::string::npos);
    REQUIRE(html.find("figure { margin: 0 0 1.5em; break-inside: avoid; page-break-inside: avoid; }") != std::string::npos);
    // Two pictures of at most 10.5 cm and their captions fit a US Letter sheet (279 mm) less its
    // 12 mm margins: 2 x 105 mm + 2 x 15 mm of caption and space = 240 mm < 255 mm.
    REQUIRE(html.find("max-height: 10.5cm") != std::string::npos);
    REQUIRE(html.find("@page { margin: 12mm; }") != std::string::npos);
}

TEST_CASE("a handout without pages says so in its index", "[handout]")
{
    const std::string html = handout_index_html("quiet.keys", {});
    REQUIRE(html.find("<figure>") == std::string::npos);
    REQUIRE(html.find("<p>The replay showed no caption, so the handout has no page.</p>") != std::string::npos);
    REQUIRE(html.ends_with("</body>\n</html>\n"));
}
