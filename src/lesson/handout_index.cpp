#include "apcs/lesson/handout_index.h"

#include "apcs/base/utf8.h"

namespace apcs {

namespace {

// Print rules: the sheet's printable height less its margins holds two pictures of at most 10.5 cm
// and their captions on A4 (297 mm) and on US Letter (279 mm) alike.
constexpr std::string_view index_style = R"(<style>
body { font-family: sans-serif; margin: 1em; color: black; background: white; }
h1 { font-size: 14pt; margin: 0 0 0.5em; }
figure { margin: 0 0 1.5em; break-inside: avoid; page-break-inside: avoid; }
figure img { display: block; max-width: 100%; max-height: 10.5cm; width: auto; height: auto; }
figcaption { font-size: 11pt; margin-top: 0.3em; }
@page { margin: 12mm; }
@media print {
  body { margin: 0; }
  figure:nth-of-type(2n) { break-after: page; page-break-after: always; }
  figure:last-of-type { break-after: auto; page-break-after: auto; }
}
</style>
)";

constexpr std::string_view index_head = "<!DOCTYPE html>\n<html>\n<head>\n<meta charset=\"utf-8\">\n<title>";

std::string figure_html(const HandoutPage& page)
{
    const std::string caption = html_escaped(page.caption);
    return "<figure>\n<img src=\"" + html_escaped(page.picture) + "\" alt=\"" + caption + "\">\n<figcaption>" +
           std::to_string(page.number) + ". " + caption + "</figcaption>\n</figure>\n";
}

} // namespace

std::string html_escaped(std::string_view text)
{
    std::string escaped;
    escaped.reserve(text.size());
    // Decoded, so that a caption's invalid bytes reach the page as U+FFFD, as they reach the .txt
    // page, not as bytes a browser guesses at.
    for (const char32_t character : decode_utf8(text)) {
        switch (character) {
        case U'&': escaped += "&amp;"; break;
        case U'<': escaped += "&lt;"; break;
        case U'>': escaped += "&gt;"; break;
        case U'"': escaped += "&quot;"; break;
        case U'\'': escaped += "&#39;"; break;
        default: append_utf8(escaped, character);
        }
    }
    return escaped;
}

std::string handout_index_html(std::string_view title, const std::vector<HandoutPage>& pages)
{
    const std::string heading = html_escaped(title);
    std::string html = std::string(index_head) + heading + "</title>\n";
    html += index_style;
    html += "</head>\n<body>\n<h1>" + heading + "</h1>\n";
    if (pages.empty())
        html += "<p>The replay showed no caption, so the handout has no page.</p>\n";
    for (const HandoutPage& page : pages)
        html += figure_html(page);
    html += "</body>\n</html>\n";
    return html;
}

bool is_handout_index(std::string_view html)
{
    return html.starts_with(index_head) && html.find(index_style) != std::string_view::npos;
}

} // namespace apcs
