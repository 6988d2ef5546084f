#pragma once
// TextCursor: a position in a text buffer with its 1-based line, for line-aware tokenising of text formats.
// Lines end at '\n'; a '\r' before it (CRLF) or alone is whitespace.

#include <charconv>
#include <cmath>
#include <cstddef>
#include <string>
#include <string_view>

namespace kumite {

class TextCursor {
public:
    explicit TextCursor(std::string_view text) : m_text(text) {}

    int line() const { return m_line; }
    std::size_t offset() const { return m_pos; }
    bool at_end() const { return m_pos >= m_text.size(); }
    std::size_t remaining_bytes() const { return m_text.size() - m_pos; }

    static bool is_blank(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v'; }

    // Skips blanks and line ends.
    void skip_whitespace() {
        while (m_pos < m_text.size() && (is_blank(m_text[m_pos]) || m_text[m_pos] == '\n')) {
            if (m_text[m_pos] == '\n') ++m_line;
            ++m_pos;
        }
    }

    // Skips blanks on the current line only.
    void skip_blanks() {
        while (m_pos < m_text.size() && is_blank(m_text[m_pos])) ++m_pos;
    }

    bool at_line_end() const { return m_pos >= m_text.size() || m_text[m_pos] == '\n'; }

    // The next whitespace-delimited token (possibly on a later line); empty at the end of the text.
    std::string_view next_token() {
        skip_whitespace();
        const std::size_t start = m_pos;
        while (m_pos < m_text.size() && !is_blank(m_text[m_pos]) && m_text[m_pos] != '\n') ++m_pos;
        return m_text.substr(start, m_pos - start);
    }

    // The rest of the current line with surrounding blanks removed; the cursor stays before the line end.
    std::string_view rest_of_line() {
        skip_blanks();
        const std::size_t start = m_pos;
        while (m_pos < m_text.size() && m_text[m_pos] != '\n') ++m_pos;
        std::size_t end = m_pos;
        while (end > start && is_blank(m_text[end - 1])) --end;
        return m_text.substr(start, end - start);
    }

    // Parses a finite number at the cursor (after blanks on this line): "1", "-.5", "2.", "+3", "1e-05".
    // Returns false without moving when the next characters are not a number.
    bool parse_number(double& value) {
        skip_blanks();
        const char* first = m_text.data() + m_pos;
        const char* last = m_text.data() + m_text.size();
        if (first < last && *first == '+') ++first;
        const auto [end, error] = std::from_chars(first, last, value);
        if (error != std::errc() || !std::isfinite(value)) return false;
        if (end < last && !is_blank(*end) && *end != '\n') return false; // "1.5abc"
        m_pos = static_cast<std::size_t>(end - m_text.data());
        return true;
    }

    // The token at the cursor on this line, for error messages; at most 24 characters.
    std::string peek_for_message() {
        skip_blanks();
        if (at_line_end()) return "end of line";
        std::size_t end = m_pos;
        while (end < m_text.size() && !is_blank(m_text[end]) && m_text[end] != '\n' && end - m_pos < 24) ++end;
        return "'" + std::string(m_text.substr(m_pos, end - m_pos)) + "'";
    }

private:
    std::string_view m_text;
    std::size_t m_pos = 0;
    int m_line = 1;
};

} // namespace kumite
