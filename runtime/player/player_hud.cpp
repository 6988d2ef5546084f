// The player window's heads-up text (player_hud.h).

#include "player_hud.h"

#include <filesystem>

namespace kumite::view {
namespace {

QString share_text(long long part, long long whole) {
    return whole > 0 ? QString(" (%1%)").arg(100.0 * double(part) / double(whole), 0, 'f', 0) : QString();
}

// The drill as it runs: the part and the one after, then what comes next and how many are left (or how long, free
// sparring).
QString drill_text(const Bout& bout) {
    const DrillRun* drill = bout.drill();
    if (!drill) return {};
    const DrillRun::Status status = drill->status(bout.now_s());
    const QString name = QString::fromStdString(drill->drill().name);
    if (status.part < 0) return QString("drill %1: over\n").arg(name);
    QString text = QString("drill %1: part %2/%3 '%4' (%5)")
                       .arg(name)
                       .arg(status.part + 1)
                       .arg(status.parts)
                       .arg(QString::fromStdString(status.part_info->name))
                       .arg(bout.difficulty());
    if (status.part + 1 < status.parts) text += QString(", then '%1'").arg(QString::fromStdString(drill->drill().parts[std::size_t(status.part + 1)].name));
    if (status.part_info->free_sparring) {
        text += QString("\n    free sparring, %1 s left").arg(status.part_left_s, 0, 'f', 0);
    } else {
        text += QString("\n    %1 attack(s) left").arg(status.attacks_left);
        if (status.next) text += QString(", next: %1 in %2 s").arg(QString::fromStdString(status.next->text)).arg(status.next->t_s - bout.now_s(), 0, 'f', 1);
    }
    return text + "\n";
}

} // namespace

QString bout_status_text(const Bout& bout, double fps) {
    const BoutCounters& c = bout.counters();
    const Fighter& fighter = bout.fighter(0);
    QString lines = QString("%1  |  %2  |  aim %6  |  %3 fps  |  frame %4 us  |  %5 fighter(s)\n")
                        .arg(fighter_state_name(fighter.state()))
                        .arg(QString::fromStdString(bout.character_name(fighter.character())))
                        .arg(fps, 0, 'f', 0)
                        .arg(c.frame_us.last(), 0, 'f', 0)
                        .arg(bout.fighter_count())
                        .arg(fighter_aim_name(fighter.aim()));
    lines += QString("strikes %1: %2 hits, %3 misses  |  last contact error %4  |  %5\n")
                 .arg(c.strikes)
                 .arg(c.hits)
                 .arg(c.misses)
                 .arg(c.last_contact_error_m < 0 ? QString("-") : QString("%1 cm (%2)").arg(c.last_contact_error_m * 100.0, 0, 'f', 1).arg(c.last_hit ? "hit" : "miss"))
                 .arg(bout.head() ? "head tracked" : "no head");
    // The running session summary (what `kumite report` draws at the end); defended: blocked or slipped, of the
    // user's strikes that would land.
    const long long would_land = c.blocked + c.slipped + c.hit_by_user;
    lines += QString("session: hits %1/%2%3  |  defended %4/%5%6  |  orders %7: %8 performed, %9 refused, %10 expired\n")
                 .arg(c.hits)
                 .arg(c.strikes)
                 .arg(share_text(c.hits, c.strikes))
                 .arg(c.blocked + c.slipped)
                 .arg(would_land)
                 .arg(share_text(c.blocked + c.slipped, would_land))
                 .arg(c.orders)
                 .arg(c.orders_performed)
                 .arg(c.ignored_orders)
                 .arg(c.orders_expired);
    lines += drill_text(bout);
    if (const CaptureUser* capture = bout.tracker().capture()) {
        lines += QString("user: recorded, %1 at %2 s of %3 s (%4 m away, loops)\n")
                     .arg(QString::fromStdString(std::filesystem::path(capture->path()).filename().string()))
                     .arg(capture->capture_time_s(), 0, 'f', 1)
                     .arg(capture->duration_s(), 0, 'f', 1)
                     .arg(capture->placement().distance_m, 0, 'f', 2);
    }
    if (c.user_strikes > 0 || bout.hands().present[0] || bout.hands().present[1]) {
        lines += QString("defence %1  |  user strikes %2: %3 blocked, %4 slipped, %5 landed\n")
                     .arg(fighter.defence_enabled() ? "on" : "off")
                     .arg(c.user_strikes)
                     .arg(c.blocked)
                     .arg(c.slipped)
                     .arg(c.hit_by_user);
    }
    return lines;
}

} // namespace kumite::view
