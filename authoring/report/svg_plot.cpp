// SVG pieces for the session report (svg_plot.h).

#include "svg_plot.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace kumite::report {

std::string escape_html(std::string_view text) {
    std::string out;
    out.reserve(text.size());
    for (const char c : text) {
        switch (c) {
        case '&': out += "&amp;"; break;
        case '<': out += "&lt;"; break;
        case '>': out += "&gt;"; break;
        case '"': out += "&quot;"; break;
        case '\'': out += "&#39;"; break;
        default: out += c;
        }
    }
    return out;
}

std::string px(double value) {
    if (!std::isfinite(value)) value = 0.0;
    value = std::clamp(value, -1e6, 1e6);
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%.1f", value);
    std::string text = buffer;
    if (text.size() > 2 && text.ends_with(".0")) text.resize(text.size() - 2);
    return text == "-0" ? "0" : text;
}

std::string fixed(double value, int decimals) {
    if (!std::isfinite(value)) return "–";
    char buffer[64];
    std::snprintf(buffer, sizeof buffer, "%.*f", std::clamp(decimals, 0, 6), std::clamp(value, -1e15, 1e15));
    return buffer;
}

Ticks nice_ticks(double lo, double hi, int count) {
    if (!std::isfinite(lo) || !std::isfinite(hi) || hi <= lo) return {lo, 1.0, 1};
    const double raw = (hi - lo) / std::max(1, count);
    const double magnitude = std::pow(10.0, std::floor(std::log10(raw)));
    double step = magnitude;
    for (const double factor : {1.0, 2.0, 5.0, 10.0}) {
        step = factor * magnitude;
        if (step >= raw) break;
    }
    Ticks ticks;
    ticks.step = step;
    ticks.first = std::ceil(lo / step - 1e-9) * step;
    ticks.count = std::max(1, static_cast<int>(std::floor((hi - ticks.first) / step + 1e-9)) + 1);
    ticks.count = std::min(ticks.count, 1000);
    return ticks;
}

double median(std::vector<double> values) {
    if (values.empty()) return 0.0;
    const std::size_t middle = values.size() / 2;
    std::nth_element(values.begin(), values.begin() + std::ptrdiff_t(middle), values.end());
    return values[middle];
}

std::string histogram_svg(const std::vector<double>& values, const HistogramSpec& spec) {
    constexpr double width = 280.0, height = 180.0, left = 40.0, right = 14.0, top = 38.0, bottom = 38.0;
    const double plot_w = width - left - right, plot_h = height - top - bottom;
    std::string svg = "<svg class=\"histogram " + spec.css_class + "\" width=\"" + px(width) + "\" height=\"" + px(height) +
                      "\" viewBox=\"0 0 " + px(width) + " " + px(height) + "\" role=\"img\" aria-label=\"" + escape_html(spec.title) + "\">";
    std::vector<double> scaled;
    scaled.reserve(values.size());
    for (const double v : values) {
        if (std::isfinite(v)) scaled.push_back(v * spec.scale);
    }
    const double med = median(scaled);
    svg += "<text x=\"4\" y=\"14\" class=\"title\">" + escape_html(spec.title) + "</text>";
    if (!scaled.empty()) {
        svg += "<text x=\"4\" y=\"29\" class=\"label\">median <tspan class=\"median\">" + fixed(med, med < 10 ? 1 : 0) + "</tspan> " + escape_html(spec.unit) +
               " (dashed), " + std::to_string(scaled.size()) + " values</text>";
    }
    if (scaled.empty()) return svg + "<text x=\"" + px(left) + "\" y=\"" + px(top + plot_h / 2) + "\" class=\"note\">no values</text></svg>";

    // The range: from 0 (or the least value, when negative) to the largest, the top 1% drawn in the last bin.
    std::vector<double> sorted = scaled;
    std::sort(sorted.begin(), sorted.end());
    const double lo = std::min(0.0, sorted.front());
    double hi = sorted[std::min(sorted.size() - 1, static_cast<std::size_t>(0.99 * double(sorted.size())))];
    if (hi <= lo) hi = lo + 1.0;
    const Ticks ticks = nice_ticks(lo, hi, 5);
    hi = std::max(hi, ticks.at(ticks.count - 1));
    constexpr int bins = 20;
    std::vector<int> counts(bins, 0);
    for (const double v : scaled) {
        const int bin = std::clamp(static_cast<int>((v - lo) / (hi - lo) * bins), 0, bins - 1);
        ++counts[std::size_t(bin)];
    }
    const int most = *std::max_element(counts.begin(), counts.end());
    const double bin_w = plot_w / bins;
    for (int b = 0; b < bins; ++b) {
        if (counts[std::size_t(b)] == 0) continue;
        const double h = plot_h * counts[std::size_t(b)] / most;
        svg += "<rect x=\"" + px(left + b * bin_w + 0.5) + "\" y=\"" + px(top + plot_h - h) + "\" width=\"" + px(bin_w - 1.0) + "\" height=\"" +
               px(h) + "\" fill=\"" + colour::sky + "\"><title>" + std::to_string(counts[std::size_t(b)]) + "</title></rect>";
    }
    // Axes: counts up the left (0 and the tallest bin), values along the bottom.
    svg += "<line x1=\"" + px(left) + "\" y1=\"" + px(top + plot_h) + "\" x2=\"" + px(left + plot_w) + "\" y2=\"" + px(top + plot_h) + "\" class=\"axis\"/>";
    svg += "<line x1=\"" + px(left) + "\" y1=\"" + px(top) + "\" x2=\"" + px(left) + "\" y2=\"" + px(top + plot_h) + "\" class=\"axis\"/>";
    svg += "<text x=\"" + px(left - 4) + "\" y=\"" + px(top + 4) + "\" class=\"tick\" text-anchor=\"end\">" + std::to_string(most) + "</text>";
    svg += "<text x=\"" + px(left - 4) + "\" y=\"" + px(top + plot_h) + "\" class=\"tick\" text-anchor=\"end\">0</text>";
    const int decimals = ticks.step >= 1.0 ? 0 : ticks.step >= 0.1 ? 1 : 2;
    for (int i = 0; i < ticks.count; ++i) {
        const double x = left + (ticks.at(i) - lo) / (hi - lo) * plot_w;
        svg += "<line x1=\"" + px(x) + "\" y1=\"" + px(top + plot_h) + "\" x2=\"" + px(x) + "\" y2=\"" + px(top + plot_h + 4) + "\" class=\"axis\"/>";
        svg += "<text x=\"" + px(x) + "\" y=\"" + px(top + plot_h + 16) + "\" class=\"tick\" text-anchor=\"middle\">" + fixed(ticks.at(i), decimals) + "</text>";
    }
    svg += "<text x=\"" + px(left + plot_w / 2) + "\" y=\"" + px(height - 4) + "\" class=\"label\" text-anchor=\"middle\">" + escape_html(spec.unit) +
           "</text>";
    const double mx = left + std::clamp((med - lo) / (hi - lo), 0.0, 1.0) * plot_w;
    svg += "<line x1=\"" + px(mx) + "\" y1=\"" + px(top - 2) + "\" x2=\"" + px(mx) + "\" y2=\"" + px(top + plot_h) + "\" stroke=\"" + colour::vermillion +
           "\" stroke-width=\"2\" stroke-dasharray=\"4 2\"><title>median</title></line>";
    return svg + "</svg>";
}

} // namespace kumite::report
