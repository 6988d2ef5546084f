#pragma once
// Progress of long work (bake, play) on stdout: a bar redrawn in place on a terminal, plain lines otherwise
// (a line per stage and at each quarter, so logs stay short).

#include <chrono>
#include <iosfwd>
#include <string>

namespace kumite::cli {

class ProgressDisplay {
public:
    explicit ProgressDisplay(std::ostream& out); // a bar when `out` is std::cout and stdout is a terminal
    ProgressDisplay(std::ostream& out, bool terminal);
    ~ProgressDisplay();

    void update(const std::string& stage, int done, int total);
    void finish(); // ends the bar's line

private:
    std::ostream& m_out;
    bool m_terminal;
    std::string m_stage;
    int m_last_quarter = -1;
    bool m_bar_open = false;
    std::chrono::steady_clock::time_point m_last_draw{};
};

} // namespace kumite::cli
