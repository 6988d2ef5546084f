#pragma once
// A trainee's progress across the sessions of the training store (training_store.h): the numbers of each session,
// the first-versus-last comparison of every drill run more than once, and the page that shows them (one
// self-contained HTML file: inline CSS and SVG, no script, nothing fetched). Times are seconds; shares are 0..1.

#include "training_store.h"

#include <map>
#include <string>
#include <vector>

namespace kumite::training {

// The spread of some times: the median and quartiles (linear interpolation between order statistics, as numpy's and
// pandas' default), NaN with n = 0 when there are none.
struct TimeSpread {
    int n = 0;
    double median_s = k_no_value;
    double p25_s = k_no_value;
    double p75_s = k_no_value;
};
TimeSpread time_spread(std::vector<double> times_s);

// "punch straight high": the command, kind and height of an attack, the parts that are given.
std::string attack_name(const AttackRow& attack);

// One session in numbers. The response times are those of answers that began after the blow showed (0 s or more);
// an answer that began before is counted as anticipated and left out of the times, as the session report does.
struct SessionProgress {
    SessionRow session;
    std::vector<double> response_times_s;                               // in the session's order
    std::map<std::string, std::vector<double>> response_times_by_attack_s; // attack_name → its times
    std::map<std::string, int> attacks_by_name;                          // attack_name → its blows, answered or not
    TimeSpread response_time;
    int anticipated = 0;
    int in_time = 0, late = 0, no_answer = 0;           // the attacks by quality
    int fighter_hit = 0, fighter_blocked = 0, fighter_missed = 0; // the attacks by the blow's result
    int attacks = 0;                                    // the attack rows read (the session's count as stored)
    int user_strikes = 0, user_landed = 0, user_defended = 0;     // landed on the fighter; defended by it
};

// First versus last session of one drill run at least twice.
struct DrillComparison {
    std::string drill;
    bool reaction_test = false; // the drill's name says "reaction": a pre-/post-test
    int runs = 0;
    std::size_t first = 0, last = 0; // indices into the sessions
};

// The trainee's sessions, oldest first, with their numbers. An unknown trainee is StoreReader::check_trainee's error
// (it names the trainees the store has).
Result<std::vector<SessionProgress>> session_progress(const StoreReader& store, const std::string& trainee);
// Every drill run at least twice, reaction tests first, then by name.
std::vector<DrillComparison> drill_comparisons(const std::vector<SessionProgress>& sessions);

// The share part / whole, NaN when whole is 0.
double share(int part, int whole);

// The progress page of a trainee (session_progress's error for an unknown one).
Result<std::string> progress_html(const StoreReader& store, const std::string& trainee);
// The same page from sessions already read (session_progress), so a caller printing their numbers shows the same rows.
std::string progress_html(const std::string& trainee, const std::vector<SessionProgress>& sessions);

} // namespace kumite::training
