#include "kumite/runtime/bout.h"

#include "bout/own_attacks.h"
#include "kumite/runtime/combinations.h"
#include "kumite/runtime/difficulty.h"

#include <algorithm>
#include <cmath>
#include <chrono>

namespace kumite {

struct Bout::Character {
    std::string name;
    BvhFile file;
    std::shared_ptr<const SkinnedMesh> body;
    RestAnatomy anatomy;
    std::unique_ptr<CharacterRig> rig;
};

Bout::~Bout() = default;

Result<std::unique_ptr<Bout>> Bout::create(const MotionDatabaseView& database, std::vector<BoutCharacter> characters,
                                           std::unique_ptr<HeadTracker> tracker, const BoutOptions& options) {
    if (characters.empty()) return make_error(ErrorCode::invalid, "a bout needs at least one character");
    if (options.start_character < 0 || options.start_character >= int(characters.size())) return make_error(ErrorCode::invalid, "no such starting character");
    if (options.fighters < 1) return make_error(ErrorCode::invalid, "a bout needs at least one fighter");
    if (!tracker) return make_error(ErrorCode::invalid, "a bout needs a head tracker");
    std::unique_ptr<Bout> bout(new Bout());
    bout->m_db = database;
    bout->m_counters.by_clip.assign(database.clips.size(), {0, 0});
    bout->m_options = options;
    bout->m_tracker = std::move(tracker);
    for (BoutCharacter& given : characters) {
        auto character = std::make_unique<Character>();
        character->name = std::move(given.name);
        character->file = std::move(given.file);
        character->body = std::move(given.body);
        if (character->body && character->body->bind_to_rest.size() != std::size_t(character->file.clip.skeleton.joint_count())) {
            return make_error(ErrorCode::invalid, "character " + character->name + ": its body is bound to another skeleton");
        }
        Result<RestAnatomy> anatomy = rest_anatomy_build(character->file.clip, character->file.body_map);
        if (!anatomy) return make_error(anatomy.error().code, "character " + character->name + ": " + anatomy.error().message);
        character->anatomy = std::move(*anatomy);
        character->rig = std::make_unique<CharacterRig>(character->file.clip.skeleton, character->anatomy);
        bout->m_characters.push_back(std::move(character));
    }
    std::vector<CharacterRig*> rigs;
    const int count = int(bout->m_characters.size());
    for (int i = 0; i < count; ++i) rigs.push_back(bout->m_characters[(options.start_character + i) % count]->rig.get());

    RetrievalSettings retrieval_settings;
    retrieval_settings.min_lead_frames = std::max(1, int(std::lround(options.lead_s / database.meta.frame_time_s)));
    retrieval_settings.contact_extension = options.contact_extension;
    retrieval_settings.contact_speed_share = options.contact_speed_share;
    bout->m_retriever = std::make_unique<Retriever>(database, retrieval_settings);
    const std::shared_ptr<const LibrarySpeeds> library_speeds = measure_library_speeds(database, rigs); // once for every fighter
    for (int i = 0; i < options.fighters; ++i) {
        FighterSettings settings = options.fighter;
        settings.rate_hz = options.rate_hz;
        settings.start_x_m = (double(i) - 0.5 * double(options.fighters - 1)) * 1.2;
        bout->m_fighters.push_back(std::make_unique<Fighter>(database, *bout->m_retriever, rigs, settings, library_speeds));
    }
    bout->m_events.reserve(std::size_t(options.fighters) * 64);
    bout->m_tallies.assign(std::size_t(options.fighters), FighterTally{});
    for (auto& fighter : bout->m_fighters) bout->m_fighter_pointers.push_back(fighter.get());
    bout->m_planning = std::make_unique<PlanningBudget>(options.plans_per_frame, bout->m_fighters.size());
    bout->m_queued.reserve(16);
    bout->m_motion = std::make_unique<MotionMeter>(options.fighters);
    std::array<bool, k_combination_count> servable{}; // the combinations whose every blow the database has
    for (std::size_t c = 0; c < k_combination_count; ++c) {
        servable[c] = true;
        for (const CombinationBlow& b : combinations()[c].blows) {
            const int semantics = bout->m_retriever->semantics_id(b.semantics);
            servable[c] = servable[c] && semantics >= 0 && bout->m_retriever->candidate_count(semantics, b.side, b.kind, b.height) > 0;
        }
    }
    bout->m_own_attacks = std::make_unique<OwnAttacks>(options.attacks, options.attack_seed, servable);
    if (options.record) {
        const Character& start = *bout->m_characters[options.start_character];
        bout->m_record_decoder = std::make_unique<MirDecoder>(start.file.clip.skeleton, start.anatomy, std::span<const std::string>{});
        bout->m_recording.skeleton = start.file.clip.skeleton;
        bout->m_recording.frame_time_s = 1.0 / options.rate_hz;
    }
    return bout;
}

const std::string& Bout::character_name(int fighter_character) const {
    return m_characters[(m_options.start_character + fighter_character) % m_characters.size()]->name;
}

const Skeleton& Bout::character_skeleton(int fighter_character) const {
    return m_characters[(m_options.start_character + fighter_character) % m_characters.size()]->file.clip.skeleton;
}

const RestAnatomy& Bout::character_anatomy(int fighter_character) const {
    return m_characters[(m_options.start_character + fighter_character) % m_characters.size()]->anatomy;
}

const std::shared_ptr<const SkinnedMesh>& Bout::character_body(int fighter_character) const {
    return m_characters[(m_options.start_character + fighter_character) % m_characters.size()]->body;
}

const BvhFile& Bout::starting_character_file() const { return m_characters[m_options.start_character]->file; }

int Bout::fighter_character_of(const std::string& name) const {
    for (int i = 0; i < character_count(); ++i) {
        if (character_name(i) == name) return i;
    }
    return -1;
}

Result<void> Bout::command(std::string_view line) {
    Result<SupervisorCommand> parsed = supervisor_command_parse(line);
    if (!parsed) return parsed.error();
    if (parsed->verb == SupervisorCommand::Verb::character && fighter_character_of(parsed->argument) < 0) {
        return make_error(ErrorCode::invalid, "unknown character '" + parsed->argument + "'");
    }
    m_queued.emplace_back(line);
    return {};
}

void Bout::apply(std::string_view line, const std::string& where, bool own) {
    Result<SupervisorCommand> command = supervisor_command_parse(line);
    if (command && command->verb == SupervisorCommand::Verb::character && fighter_character_of(command->argument) < 0) {
        command = make_error(ErrorCode::invalid, "unknown character '" + command->argument + "'");
    }
    if (!command) {
        tell("error: " + where + command.error().message + "; ignored\n");
        return;
    }
    switch (command->verb) {
    case SupervisorCommand::Verb::punch:
    case SupervisorCommand::Verb::kick:
    case SupervisorCommand::Verb::slash:
    case SupervisorCommand::Verb::knee:
    case SupervisorCommand::Verb::elbow: {
        StrikeOrder order;
        order.side = command->side == "left" ? Side::left : command->side == "right" ? Side::right : Side::none;
        order.kind = command->kind;
        order.height = command->height;
        order.semantics = m_retriever->semantics_id(command->semantics());
        order.own = own;
        m_tracker->on_order(m_now_s);
        for (auto& fighter : m_fighters) fighter->order(order);
        break;
    }
    case SupervisorCommand::Verb::combo: {
        // Its blows in turn; a later one only after the one before it was accepted.
        const int index = combination_index(command->argument);
        const Combination& combination = combinations()[std::size_t(index)];
        m_tracker->on_order(m_now_s);
        for (auto& fighter : m_fighters) {
            for (int blow = 0; blow < int(combination.blows.size()); ++blow) {
                const CombinationBlow& b = combination.blows[std::size_t(blow)];
                const StrikeOrder order{m_retriever->semantics_id(b.semantics), b.side, b.kind, b.height, index, blow, own};
                if (!fighter->order(order)) break;
            }
        }
        break;
    }
    case SupervisorCommand::Verb::character: {
        const int index = fighter_character_of(command->argument);
        for (auto& fighter : m_fighters) fighter->set_character(index);
        break;
    }
    case SupervisorCommand::Verb::aim: {
        const FighterAim aim = fighter_aim_from_name(command->argument).value_or(FighterAim::latched);
        for (auto& fighter : m_fighters) fighter->set_aim(aim);
        break;
    }
    case SupervisorCommand::Verb::defence:
        for (auto& fighter : m_fighters) fighter->set_defence(command->argument == "on");
        break;
    case SupervisorCommand::Verb::difficulty: {
        DefenceSettings defence = m_fighters.front()->defence().settings();
        AttackSettings attacks = m_own_attacks->settings();
        difficulty_apply(*difficulty_find(command->argument), defence, attacks);
        set_pace(defence, attacks);
        break;
    }
    case SupervisorCommand::Verb::spar: {
        AttackSettings attacks = m_own_attacks->settings();
        attacks.on_its_own = command->argument == "on";
        set_pace(m_fighters.front()->defence().settings(), attacks);
        break;
    }
    case SupervisorCommand::Verb::quit: m_quit = true; break;
    }
}

void Bout::tell(std::string_view message) {
    if (m_stream) m_stream->reply(message);
    else if (m_message) m_message(message);
}

void Bout::step(double t_s) {
    const auto started = std::chrono::steady_clock::now();
    m_now_s = t_s;
    m_events.clear();
    take_head(t_s);
    apply_commands(t_s);
    m_planning->grant(m_fighter_pointers); // after the frame's orders: who plans a strike this frame
    for (std::size_t f = 0; f < m_fighters.size(); ++f) {
        Fighter& fighter = *m_fighters[f];
        fighter.step(t_s, head(), &m_tracker->hands());
        take_events(f, fighter);
        m_motion->measure(int(f), t_s, fighter, m_db, character_anatomy(fighter.character()), head());
    }
    record_first_fighter();
    count_frame(started);
}

void Bout::take_head(double t_s) {
    // Simulated users punch at the first fighter as it was last frame.
    const Fighter& first = *m_fighters.front();
    m_tracker->set_opponent_limbs({first.part_position(BodyPart::hand_l), first.part_position(BodyPart::hand_r), first.part_position(BodyPart::foot_l),
                                   first.part_position(BodyPart::foot_r)});
    m_tracker->set_opponent(first.part_position(BodyPart::head), first.part_position(BodyPart::chest),
                            first.state() != FighterState::strike && first.state() != FighterState::recover);
    const Eigen::Vector3d* tracked = m_tracker->head(t_s);
    if (const char* notice = m_tracker->take_notice()) tell(notice);
    m_have_head = tracked != nullptr;
    if (tracked) m_head = *tracked;
}

void Bout::apply_drill_line(const DrillRun::Line& line) {
    switch (line.kind) {
    case DrillRun::Line::Kind::part_start: {
        const DrillPart& part = m_drill->drill().parts[std::size_t(line.part)];
        DefenceSettings defence = m_fighters.front()->defence().settings();
        AttackSettings attacks = m_own_attacks->settings();
        if (const DifficultyLevel* level = difficulty_find(part.difficulty.text)) {
            difficulty_apply(*level, defence, attacks);
        } else { // the bout's own
            defence.reaction_delay_s = m_options.fighter.defence.reaction_delay_s;
            defence.defend_share = m_options.fighter.defence.defend_share;
            attacks = m_options.attacks;
        }
        attacks.on_its_own = part.free_sparring;
        set_pace(defence, attacks);
        break;
    }
    case DrillRun::Line::Kind::attack: apply(line.text, "drill line " + std::to_string(line.source_line) + ": "); break;
    case DrillRun::Line::Kind::end: m_quit = true; break;
    }
}

void Bout::set_pace(const DefenceSettings& defence, const AttackSettings& attacks) {
    for (auto& fighter : m_fighters) fighter->set_reaction(defence.reaction_delay_s, defence.defend_share);
    m_own_attacks->set_settings(attacks);
}

const char* Bout::difficulty() const { return difficulty_of(m_fighters.front()->defence().settings(), m_own_attacks->settings()); }

void Bout::apply_commands(double t_s) {
    if (m_drill) m_drill->due(t_s, [&](const DrillRun::Line& line) { apply_drill_line(line); });
    if (m_has_script) m_script.due(t_s, [&](const CommandScript::Line& line) { apply(line.command, "line " + std::to_string(line.line) + ": "); });
    if (m_stream) m_stream->poll([&](std::string_view line) { apply(line, ""); });
    for (const std::string& line : m_queued) apply(line, "");
    m_queued.clear();
    // The fighter's own attack, when one is due and it is free: no order waiting, resting or stepping.
    const Fighter& first = *m_fighters.front();
    const bool free = !first.has_waiting_order() && (first.state() == FighterState::rest || first.state() == FighterState::approach) && m_have_head;
    if (const std::string& attack = m_own_attacks->due(t_s, free); !attack.empty()) apply(attack, "", true);
}

void Bout::take_events(std::size_t fighter_index, Fighter& fighter) {
    for (const FighterEvent& event : fighter.events()) {
        m_counters.tally(event, m_counters.frames, m_db, m_tallies[fighter_index]);
        if (m_events.size() < m_events.capacity()) m_events.push_back({int(fighter_index), event});
    }
    fighter.clear_events();
}

void Bout::record_first_fighter() {
    if (!m_record_decoder) return;
    m_record_decoder->decode(m_record_pose, m_fighters[0]->mir());
    clip_append_pose(m_recording, m_record_pose.view());
}

void Bout::count_frame(std::chrono::steady_clock::time_point started) {
    ++m_counters.frames;
    const double elapsed_us = std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - started).count();
    m_counters.frame_us.add(elapsed_us);
    m_counters.missed_frames += elapsed_us > 1e6 / m_options.rate_hz;
}

} // namespace kumite
