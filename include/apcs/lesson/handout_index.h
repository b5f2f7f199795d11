#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace apcs {

// DIR/index.html of a handout (--handout DIR, SPEC §3.1): every page's picture and caption in the
// script's order, one document a teacher opens in a browser and prints.

// One page of the index: its caption's number in the script (from 1), its picture's file name
// (beside index.html) and its caption.
struct HandoutPage {
    int number = 0;
    std::string picture;
    std::string caption;
};

// `text` for HTML, as text or as an attribute's value: & < > " ' as character references, every
// other character as it is (the document is UTF-8), bytes that are not UTF-8 as U+FFFD.
std::string html_escaped(std::string_view text);

// The index of a handout titled `title` (the key script's name): a plain, self-contained HTML page
// (UTF-8, relative picture names, no script) that prints two pictures a sheet, each with its
// caption under it ("4. CAPTION", 4 the caption's number) and never split from it. A picture keeps
// its shape and fits half an A4 or US Letter sheet in portrait; a page break follows every second
// picture.
std::string handout_index_html(std::string_view title, const std::vector<HandoutPage>& pages);

// Whether `html` is an index handout_index_html wrote (its head and its print rules): how an earlier
// handout of APCS is recognised in a folder, and a page of the user's told from it.
bool is_handout_index(std::string_view html);

} // namespace apcs
