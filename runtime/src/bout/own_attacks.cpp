// The fighter's own attacks (own_attacks.h).

#include "bout/own_attacks.h"

#include "kumite/runtime/combinations.h"

#include <algorithm>

namespace kumite {

OwnAttacks::OwnAttacks(const AttackSettings& settings, std::uint64_t seed, std::array<bool, k_combination_count> servable)
    : m_settings(settings), m_random{seed ^ 0x6f776e2d61747461ULL}, m_servable(servable) {
    for (const bool can : m_servable) m_servable_count += can;
    m_line.reserve(32);
}

void OwnAttacks::set_settings(const AttackSettings& settings) {
    if (settings.on_its_own && !m_settings.on_its_own) m_next_s = -1.0;
    m_settings = settings;
}

double OwnAttacks::next_gap_s() { return m_settings.tempo_s * m_random.uniform(0.6, 1.4); }

const std::string& OwnAttacks::due(double t_s, bool free) {
    m_line.clear();
    if (!m_settings.on_its_own || !(m_settings.tempo_s > 0.0)) return m_line;
    if (m_next_s < 0.0) m_next_s = t_s + next_gap_s();
    if (t_s < m_next_s || !free) return m_line;
    if (m_random.uniform() < m_settings.combination_share && m_servable_count > 0) {
        int pick = std::min(m_servable_count - 1, int(m_random.uniform() * double(m_servable_count))); // among the servable
        std::size_t c = 0;
        for (; c < m_servable.size(); ++c) {
            if (m_servable[c] && pick-- == 0) break;
        }
        m_line = "combo ";
        m_line += combinations()[c].name;
    } else {
        m_line = m_random.uniform() < m_settings.kick_share ? "kick" : "punch";
    }
    m_next_s = t_s + next_gap_s();
    return m_line;
}

} // namespace kumite
