#include "progress_display.h"

#include <algorithm>
#include <cstdio>
#include <iostream>
#include <unistd.h>

namespace kumite::cli {

ProgressDisplay::ProgressDisplay(std::ostream& out) : ProgressDisplay(out, &out == &std::cout && isatty(STDOUT_FILENO)) {}

ProgressDisplay::ProgressDisplay(std::ostream& out, bool terminal) : m_out(out), m_terminal(terminal) {}

ProgressDisplay::~ProgressDisplay() { finish(); }

void ProgressDisplay::update(const std::string& stage, int done, int total) {
    total = std::max(total, 1);
    done = std::clamp(done, 0, total);
    const bool new_stage = stage != m_stage;
    if (new_stage) {
        finish();
        m_stage = stage;
        m_last_quarter = -1;
    }
    if (m_terminal) {
        const auto now = std::chrono::steady_clock::now();
        if (!new_stage && done < total && now - m_last_draw < std::chrono::milliseconds(50)) return;
        m_last_draw = now;
        constexpr int width = 30;
        const int filled = done * width / total;
        char line[160];
        std::snprintf(line, sizeof line, "\r  %-20s [%s%s] %3d%%  %d/%d", stage.c_str(), std::string(filled, '#').c_str(),
                      std::string(width - filled, '.').c_str(), done * 100 / total, done, total);
        m_out << line << std::flush;
        m_bar_open = true;
        return;
    }
    const int quarter = done * 4 / total;
    if (quarter == m_last_quarter) return;
    m_last_quarter = quarter;
    m_out << "  " << stage << ": " << done << "/" << total << "\n" << std::flush;
}

void ProgressDisplay::finish() {
    if (m_bar_open) m_out << "\n" << std::flush;
    m_bar_open = false;
}

} // namespace kumite::cli
