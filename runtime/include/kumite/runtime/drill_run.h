#pragma once
// A drill (drill_file.h) as a bout runs it: its parts in turn from t = 0, each at its difficulty, with its attacks at
// their moments, or the fighter's own attacks for a free-sparring part. Compiled once, before the bout: the moments
// (the cadence drawn with the part's seed) and the attacks (in turn, or drawn at random), so the same drill gives the
// same session, and a step only hands out what is due (no allocation).
// A part with a count ends k_count_part_tail_s after its last attack (time for the blow, the answer and a counter);
// a part with a duration ends when it has lasted it. The drill ends with its last part.

#include "kumite/core/result.h"
#include "kumite/formats/drill_file.h"

#include <functional>
#include <string>
#include <vector>

namespace kumite {

inline constexpr double k_count_part_tail_s = 3.0;

class DrillRun {
public:
    struct Line {
        enum class Kind { part_start, attack, end } kind = Kind::attack;
        double t_s = 0.0;
        int part = 0;
        std::string text; // the attack's supervisor line
        int source_line = 0; // where the attack is written in the drill file
    };
    struct Part {
        double start_s = 0.0, end_s = 0.0;
        int attacks = 0;              // the attacks it orders (0 for free sparring)
        std::size_t first_line = 0;   // its part_start line in lines()
    };
    struct Status {
        int part = -1;                // -1: not started or over
        int parts = 0;
        const DrillPart* part_info = nullptr;
        const Line* next = nullptr;   // its next attack, or null (free sparring, or none left)
        int attacks_left = 0;         // in the part, not yet ordered
        double part_left_s = 0.0;
    };

    // The drill's attacks are checked as supervisor commands (strikes and combinations only) and its difficulties
    // as levels' names: an error reads "FILE:LINE: reason".
    static Result<DrillRun> compile(Drill drill, const std::string& file_name);

    // Calls `on_line` for every line due at t not handed out yet, in time order.
    void due(double t_s, const std::function<void(const Line&)>& on_line);
    Status status(double t_s) const;
    // The part running at t (the last one after the end).
    int part_at(double t_s) const;

    const Drill& drill() const { return m_drill; }
    const std::vector<Part>& parts() const { return m_parts; }
    const std::vector<Line>& lines() const { return m_lines; }
    double duration_s() const { return m_parts.empty() ? 0.0 : m_parts.back().end_s; }

private:
    Drill m_drill;
    std::vector<Part> m_parts;
    std::vector<Line> m_lines; // in time order
    std::size_t m_next = 0;
};

} // namespace kumite
