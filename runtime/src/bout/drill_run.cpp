// A drill as a bout runs it (drill_run.h).

#include "kumite/runtime/drill_run.h"

#include "kumite/core/split_mix.h"
#include "kumite/runtime/difficulty.h"
#include "kumite/runtime/supervisor.h"

#include <algorithm>

namespace kumite {
namespace {

Result<void> check_part(const DrillPart& part, const std::string& file_name) {
    const auto at = [&](int line, const std::string& reason) { return make_error(ErrorCode::parse, file_name + ":" + std::to_string(line) + ": " + reason); };
    for (const DrillLine& attack : part.attacks) {
        Result<SupervisorCommand> command = supervisor_command_parse(attack.text);
        if (!command) return at(attack.line, "'" + attack.text + "': " + command.error().message);
        if (!command->is_strike() && command->verb != SupervisorCommand::Verb::combo) {
            return at(attack.line, "'" + attack.text + "' is not an attack (a strike or a combo)");
        }
    }
    if (!part.difficulty.text.empty() && !difficulty_find(part.difficulty.text)) {
        return at(part.difficulty.line, "difficulty takes " + std::string(difficulty_names()) + ", not '" + part.difficulty.text + "'");
    }
    return {};
}

} // namespace

Result<DrillRun> DrillRun::compile(Drill drill, const std::string& file_name) {
    DrillRun run;
    double t = 0.0;
    for (std::size_t p = 0; p < drill.parts.size(); ++p) {
        const DrillPart& part = drill.parts[p];
        if (Result<void> checked = check_part(part, file_name); !checked) return checked.error();
        Part span;
        span.start_s = t;
        span.first_line = run.m_lines.size();
        run.m_lines.push_back({Line::Kind::part_start, t, int(p), {}, part.line});
        SplitMix64 random{part.seed};
        const auto gap = [&] { return part.cadence_min_s == part.cadence_max_s ? part.cadence_min_s : random.uniform(part.cadence_min_s, part.cadence_max_s); };
        const double part_end = part.count > 0 ? -1.0 : t + part.duration_s;
        if (!part.free_sparring) {
            double at = t;
            for (int k = 0; part.count > 0 ? k < part.count : true; ++k) {
                at += gap();
                if (part.count <= 0 && at >= part_end) break;
                const std::size_t pick = part.in_turn ? std::size_t(k) % part.attacks.size()
                                                      : std::min(part.attacks.size() - 1, std::size_t(random.uniform() * double(part.attacks.size())));
                run.m_lines.push_back({Line::Kind::attack, at, int(p), part.attacks[pick].text, part.attacks[pick].line});
                ++span.attacks;
            }
            t = part.count > 0 ? at + k_count_part_tail_s : part_end;
        } else {
            t = part_end;
        }
        span.end_s = t;
        run.m_parts.push_back(span);
    }
    run.m_lines.push_back({Line::Kind::end, t, int(drill.parts.size()) - 1, {}, 0});
    run.m_drill = std::move(drill);
    return run;
}

void DrillRun::due(double t_s, const std::function<void(const Line&)>& on_line) {
    while (m_next < m_lines.size() && m_lines[m_next].t_s <= t_s) on_line(m_lines[m_next++]);
}

int DrillRun::part_at(double t_s) const {
    for (std::size_t p = 0; p < m_parts.size(); ++p) {
        if (t_s < m_parts[p].end_s) return int(p);
    }
    return int(m_parts.size()) - 1;
}

DrillRun::Status DrillRun::status(double t_s) const {
    Status status;
    status.parts = int(m_parts.size());
    if (m_parts.empty() || t_s < 0.0 || t_s >= duration_s()) return status;
    status.part = part_at(t_s);
    const Part& part = m_parts[std::size_t(status.part)];
    status.part_info = &m_drill.parts[std::size_t(status.part)];
    status.part_left_s = part.end_s - t_s;
    for (std::size_t i = part.first_line + 1; i < m_lines.size() && m_lines[i].part == status.part && m_lines[i].kind == Line::Kind::attack; ++i) {
        if (m_lines[i].t_s <= t_s) continue;
        if (!status.next) status.next = &m_lines[i];
        ++status.attacks_left;
    }
    return status;
}

} // namespace kumite
