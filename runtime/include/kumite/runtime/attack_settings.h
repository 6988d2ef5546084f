#pragma once
// The fighter's own attacks, free sparring (BoutOptions::attacks; the bout's own_attacks.h throws them).

namespace kumite {

struct AttackSettings {
    bool on_its_own = false;         // attacks without orders (free sparring); a supervisor's order still comes first
    double tempo_s = 2.0;            // on its own: an attack this often on average (0.6 to 1.4 times it, at random)
    double combination_share = 0.4;  // on its own: this share of its attacks are combinations (combinations.h)
    double kick_share = 0.25;        // on its own: of its single blows, this share are kicks, the rest punches
};

} // namespace kumite
