#pragma once
// What the fighter keeps per character (private to fighter*.cpp): the rig, its strike adapter, MIR decoder and
// encoder.

#include "kumite/runtime/fighter.h"

namespace kumite {

struct Fighter::Body {
    CharacterRig* rig;
    StrikeAdapter adapter;
    MirDecoder decoder;
    MirEncoder encoder;

    Body(CharacterRig* character, const MotionDatabaseView& db)
        : rig(character), adapter(*character, db), decoder(character->skeleton(), character->anatomy(), {}),
          encoder(character->skeleton(), character->anatomy()) {}
};

} // namespace kumite
