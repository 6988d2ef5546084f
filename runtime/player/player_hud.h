#pragma once
// The bout's state as the player window's heads-up text shows it, line by line: the fighter (state, character,
// aim), the frame rate and cost, its strikes and the session so far, the drill as it runs, the recorded user, and
// the defence against the user's strikes.

#include "kumite/runtime/bout.h"

#include <QString>

namespace kumite::view {

QString bout_status_text(const Bout& bout, double fps);

} // namespace kumite::view
