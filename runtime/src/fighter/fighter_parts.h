#pragma once
// The fighter's parts (fighter.h; who calls whom: runtime/README.md). Private to the fighter's sources.

#include "fighter/character_body.h"
#include "fighter/event_log.h"
#include "fighter/fighter_defence.h"
#include "fighter/footwork.h"
#include "fighter/hit_reactions.h"
#include "fighter/motion_player.h"
#include "fighter/order_queue.h"
#include "fighter/response_watch.h"
#include "fighter/speed_limit.h"
#include "fighter/strike.h"
#include "fighter/strike_planner.h"
#include "fighter/tracked_user.h"

#include "kumite/runtime/fighter.h"

namespace kumite {

struct Fighter::Parts {
    Parts(const MotionDatabaseView& database, const Retriever& retriever, const std::vector<CharacterRig*>& characters, const FighterSettings& settings,
          std::shared_ptr<const LibrarySpeeds> library_speeds)
        : db(database), speed_limit(library_speeds ? std::move(library_speeds) : measure_library_speeds(database, characters)), user(settings.head_motion, settings.user_guard), orders(retriever, settings.order_wait_s), footwork(db, settings), player(db, footwork.guard_clip()), strike(db, settings),
          planner(db, retriever, settings), defence(db, settings.defence), reactions(db, *characters.front()), responses(settings.response),
          body(db, characters, settings.start_x_m, defence.frames(),
               std::array<MirFrame*, 4>{player.frames()[0], player.frames()[1], player.frames()[2], &strike.start_frame()}) {
        int joints = 0;
        for (const CharacterRig* character : characters) joints = std::max(joints, character->skeleton().joint_count());
        speed_limit.reserve(joints);
        speed_limit.map_limbs(characters);
    }

    const MotionDatabaseView db; // the parts' references point here
    SpeedLimit speed_limit;
    EventLog log;
    TrackedUser user;
    OrderQueue orders;
    Footwork footwork;
    MotionPlayer player;
    Strike strike;
    StrikePlanner planner;
    FighterDefence defence;
    HitReactions reactions;
    ResponseWatch responses;
    CharacterBody body; // last: it sizes the frames the others keep
};

} // namespace kumite
