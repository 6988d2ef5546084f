#pragma once
// Small pieces of inline SVG for the session report: numbers and text written safely, tick steps a reader can read,
// the colour-blind-safe palette (Okabe & Ito), and a histogram with its median.

#include <string>
#include <string_view>
#include <vector>

namespace kumite::report {

// Okabe-Ito colours: distinguishable with every common colour-vision deficiency; the report also varies shapes.
namespace colour {
inline constexpr const char* blue = "#0072B2";
inline constexpr const char* vermillion = "#D55E00";
inline constexpr const char* green = "#009E73";
inline constexpr const char* sky = "#56B4E9";
inline constexpr const char* orange = "#E69F00";
inline constexpr const char* purple = "#CC79A7";
inline constexpr const char* yellow = "#F0E442";
inline constexpr const char* grey = "#8C8C8C";
inline constexpr const char* ink = "#222222";
} // namespace colour

// The style both report pages (the session's, a trainee's progress) share: headings, paragraphs, SVG text, legends.
inline constexpr const char* k_page_style = R"(
h1 { font-size: 22px; margin: 0 0 4px; } h2 { font-size: 18px; margin: 28px 0 8px; border-bottom: 1px solid #ccc; }
h3 { font-size: 14px; margin: 14px 0 6px; } p { margin: 4px 0; }
svg text { font-family: system-ui, "DejaVu Sans", sans-serif; }
.legend { font-size: 12px; color: #333; } .key { margin-right: 14px; white-space: nowrap; } .key svg { vertical-align: -2px; margin-right: 4px; }
)";

std::string escape_html(std::string_view text);
// A coordinate or length for SVG: one decimal, no exponent, clamped to ±1e6.
std::string px(double value);
// A value for people to read: `decimals` after the point.
std::string fixed(double value, int decimals);

// Ticks from `lo` to `hi` at a 1, 2 or 5 × 10^k step giving about `count` of them.
struct Ticks {
    double first = 0.0, step = 1.0;
    int count = 0;
    double at(int i) const { return first + step * i; }
};
Ticks nice_ticks(double lo, double hi, int count);

// The median of the values (0 for none).
double median(std::vector<double> values);

struct HistogramSpec {
    std::string title;      // "command → strike"
    std::string unit;       // "ms"
    double scale = 1.0;     // values × scale are in `unit`
    std::string css_class;  // on the <svg>, for tests and styles
};
// A histogram of the values (shown in unit), with its median marked and written; "no values" when empty.
std::string histogram_svg(const std::vector<double>& values, const HistogramSpec& spec);

} // namespace kumite::report
