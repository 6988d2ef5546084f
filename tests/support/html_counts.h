#pragma once
// Reading the session report's HTML in tests: how often a piece occurs, and the count in a summary cell.

#include <regex>
#include <string>

namespace kumite::test {

inline std::size_t occurrences(const std::string& text, const std::string& needle) {
    std::size_t count = 0;
    for (std::size_t at = text.find(needle); at != std::string::npos; at = text.find(needle, at + needle.size())) ++count;
    return count;
}

// The number in the first summary cell of class `css_class` (the bout's summary comes first); -1 when none.
inline long long summary_count(const std::string& html, const std::string& css_class) {
    const std::regex cell("class=\"n " + css_class + "\"><span class=\"count\">([0-9]+)</span>");
    std::smatch match;
    return std::regex_search(html, match, cell) ? std::stoll(match[1]) : -1;
}

} // namespace kumite::test
