#pragma once
// TextCursor: a position in a text buffer with its 1-based line, for line-aware tokenising of text formats.
// Lines end at '\n'; a '\r' before it (CRLF) or alone is whitespace.

#include <charconv>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <string>
#include <string_view>

namespace kumite {

class TextCursor {
public:
    explicit TextCursor(std::string_view text) : m_text(text) {}

    // A cursor on the same text at a given offset, which must start line `line`.
    TextCursor at(std::size_t offset, int line) const {
        TextCursor cursor(m_text);
        cursor.m_pos = offset;
        cursor.m_line = line;
        return cursor;
    }

    std::string_view text() const { return m_text; }
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

    // No length, angle or time in a text format we read comes near this; beyond it a value is corrupt, and
    // keeping it out means any value we accept can be written back and read again.
    static constexpr double k_max_magnitude = 1e15;

    // Parses a number at the cursor (after blanks on this line): "1", "-.5", "2.", "+3", "1e-05", with a
    // magnitude of at most k_max_magnitude. Returns false without moving when the next characters are not one.
    bool parse_number(double& value) {
        skip_blanks();
        const char* const begin = m_text.data() + m_pos;
        const char* const end = m_text.data() + m_text.size();
        const char* p = begin;
        const bool negative = p < end && *p == '-';
        if (p < end && (*p == '-' || *p == '+')) ++p;
        const char* const number_begin = p; // from_chars takes no '+', and the sign is applied here

        // Fast path (Clinger): up to 19 significant digits and a power of ten that doubles hold exactly give
        // the correctly rounded value with one multiplication or division, the same value strtod gives.
        std::uint64_t mantissa = 0;
        const char* const integer_begin = p;
        p = accumulate_digits(p, end, mantissa);
        const std::ptrdiff_t integer_digits = p - integer_begin;
        std::ptrdiff_t fraction_digits = 0;
        if (p < end && *p == '.') {
            const char* const fraction_begin = ++p;
            p = accumulate_digits(p, end, mantissa);
            fraction_digits = p - fraction_begin;
        }
        if (integer_digits + fraction_digits == 0) return false;
        // 19 digits always fit in 64 bits; longer numbers (overflowed mantissa) take the slow path.
        const bool exact = integer_digits + fraction_digits <= 19;
        long exponent = -static_cast<long>(fraction_digits);
        if (p < end && (*p == 'e' || *p == 'E')) {
            ++p;
            const bool negative_exponent = p < end && *p == '-';
            if (p < end && (*p == '-' || *p == '+')) ++p;
            if (p >= end || !is_digit(*p)) return false;
            long written_exponent = 0;
            while (p < end && is_digit(*p)) {
                if (written_exponent < 100000) written_exponent = written_exponent * 10 + (*p - '0');
                ++p;
            }
            exponent += negative_exponent ? -written_exponent : written_exponent;
        }
        if (p < end && !is_blank(*p) && *p != '\n') return false; // "1.5abc", "1.5.5"

        double magnitude = 0.0;
        if (exact && mantissa <= (std::uint64_t(1) << 53) && exponent >= -22 && exponent <= 22) {
            magnitude = static_cast<double>(mantissa);
            magnitude = exponent < 0 ? magnitude / k_powers_of_ten[-exponent] : magnitude * k_powers_of_ten[exponent];
        } else {
            const auto [parsed_end, error] = std::from_chars(number_begin, p, magnitude);
            if (error != std::errc() || parsed_end != p) return false;
        }
        if (!(magnitude <= k_max_magnitude)) return false; // also NaN and infinity
        value = negative ? -magnitude : magnitude;
        m_pos = static_cast<std::size_t>(p - m_text.data());
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
    static bool is_digit(char c) { return c >= '0' && c <= '9'; }

    // mantissa = mantissa * 10^n + the n decimal digits at p; returns the end of the digits. Four digits at a
    // time where it can (SWAR: one 32-bit load, a digit test and two multiplications), then one by one.
    // The value may wrap past 19 digits; callers count digits and fall back then.
    static const char* accumulate_digits(const char* p, const char* end, std::uint64_t& mantissa) {
        while (end - p >= 4) {
            std::uint32_t chunk;
            std::memcpy(&chunk, p, 4);
            const std::uint32_t high_nibbles = chunk & 0xF0F0F0F0u;
            const std::uint32_t overflow = ((chunk + 0x06060606u) & 0xF0F0F0F0u);
            if (high_nibbles != 0x30303030u || overflow != 0x30303030u) break; // not four '0'..'9'
            chunk -= 0x30303030u;
            chunk = (chunk * 10 + (chunk >> 8)) & 0x00FF00FFu; // two-digit pairs, little endian
            const std::uint32_t four = (chunk & 0xFFu) * 100 + (chunk >> 16);
            mantissa = mantissa * 10000 + four;
            p += 4;
        }
        while (p < end && is_digit(*p)) mantissa = mantissa * 10 + static_cast<std::uint64_t>(*p++ - '0');
        return p;
    }
    static constexpr double k_powers_of_ten[23] = {1e0,  1e1,  1e2,  1e3,  1e4,  1e5,  1e6,  1e7,  1e8,  1e9,  1e10, 1e11,
                                                   1e12, 1e13, 1e14, 1e15, 1e16, 1e17, 1e18, 1e19, 1e20, 1e21, 1e22};

    std::string_view m_text;
    std::size_t m_pos = 0;
    int m_line = 1;
};

} // namespace kumite
