// The C API (include/kumite.h) over kumite::runtime: handles that own the C++ objects, statuses and a per-thread
// message instead of exceptions, caller-owned buffers. Every entry point catches everything: nothing crosses the
// boundary but a status.

#include "kumite.h"

#include "kumite/core/skinned_mesh.h"
#include "kumite/formats/character_catalog.h"
#include "kumite/formats/motion_database_file.h"
#include "kumite/runtime/bout.h"
#include "kumite/runtime/bout_cast.h"
#include "kumite/runtime/bout_event_json.h"

#include <cmath>
#include <cstring>
#include <exception>
#include <new>
#include <string>

struct kumite_database {
    kumite::MotionDatabase database;
};

struct kumite_bout {
    std::unique_ptr<kumite::Bout> bout;
    bool fed = false;
    std::vector<Eigen::Matrix4f> skin; // sized once to the most joints of any character
    std::size_t next_event = 0;        // into the last step's events
};

namespace {

thread_local std::string g_last_error;

kumite_status fail(kumite_status status, std::string message) {
    g_last_error = std::move(message);
    return status;
}

kumite_status status_of(const kumite::Error& error) {
    switch (error.code) {
    case kumite::ErrorCode::io: return fail(KUMITE_ERROR_IO, error.message);
    case kumite::ErrorCode::parse: return fail(KUMITE_ERROR_PARSE, error.message);
    default: return fail(KUMITE_ERROR_INVALID, error.message);
    }
}

// Runs `body`, turning anything thrown into KUMITE_ERROR_INTERNAL.
template <class Body>
kumite_status guarded(const char* where, Body&& body) noexcept {
    try {
        return body();
    } catch (const std::bad_alloc&) {
        return fail(KUMITE_ERROR_INTERNAL, std::string(where) + ": out of memory");
    } catch (const std::exception& error) {
        return fail(KUMITE_ERROR_INTERNAL, std::string(where) + ": " + error.what());
    } catch (...) {
        return fail(KUMITE_ERROR_INTERNAL, std::string(where) + ": unexpected failure");
    }
}

const kumite::Fighter* fighter_of(const kumite_bout* bout, int fighter) {
    if (!bout || fighter < 0 || fighter >= bout->bout->fighter_count()) return nullptr;
    return &bout->bout->fighter(fighter);
}

kumite_status check_fighter(const kumite_bout* bout, int fighter, const char* where) {
    if (!bout) return fail(KUMITE_ERROR_ARGUMENT, std::string(where) + ": bout is NULL");
    if (!fighter_of(bout, fighter)) {
        return fail(KUMITE_ERROR_ARGUMENT, std::string(where) + ": no fighter " + std::to_string(fighter) + " (the bout has " +
                                               std::to_string(bout->bout->fighter_count()) + ")");
    }
    return KUMITE_OK;
}

kumite_status check_buffer(const void* buffer, std::size_t count, std::size_t needed, const char* where) {
    if (!buffer) return fail(KUMITE_ERROR_ARGUMENT, std::string(where) + ": the buffer is NULL");
    if (count < needed) {
        return fail(KUMITE_ERROR_ARGUMENT, std::string(where) + ": the buffer holds " + std::to_string(count) + " values, " + std::to_string(needed) + " needed");
    }
    return KUMITE_OK;
}

void store_matrix(float* out, const Eigen::Matrix4f& matrix) { std::memcpy(out, matrix.data(), 16 * sizeof(float)); } // column-major

} // namespace

extern "C" {

const char* kumite_version(void) { return "0.1.0"; }

const char* kumite_last_error(void) { return g_last_error.c_str(); }

kumite_status kumite_database_open(const char* path, kumite_database** database) {
    return guarded("kumite_database_open", [&] {
        if (!path || !database) return fail(KUMITE_ERROR_ARGUMENT, "kumite_database_open: path and database must not be NULL");
        *database = nullptr;
        kumite::Result<kumite::MotionDatabase> opened = kumite::MotionDatabase::open(path);
        if (!opened) return status_of(opened.error());
        *database = new kumite_database{std::move(*opened)};
        return KUMITE_OK;
    });
}

void kumite_database_close(kumite_database* database) { delete database; }

int kumite_database_clip_count(const kumite_database* database) {
    if (!database) return -1;
    int strikes = 0;
    for (const kumite::DbClip& clip : database->database.view().clips) strikes += kumite::db_clip_is_strike(clip);
    return strikes;
}

void kumite_bout_options_init(kumite_bout_options* options) {
    if (!options) return;
    *options = kumite_bout_options{};
    options->fighters = 1;
    options->aim = KUMITE_AIM_LATCHED;
    options->defence = 1;
    options->seed = 1;
    options->rate_hz = 60.0;
}

kumite_status kumite_bout_create(const kumite_database* database, const kumite_bout_options* options, kumite_bout** bout) {
    return guarded("kumite_bout_create", [&] {
        if (!database || !options || !bout) return fail(KUMITE_ERROR_ARGUMENT, "kumite_bout_create: database, options and bout must not be NULL");
        *bout = nullptr;
        if (options->fighters < 1 || options->fighters > 10000) return fail(KUMITE_ERROR_ARGUMENT, "kumite_bout_create: fighters must be 1 to 10000");
        if (!(options->rate_hz >= 1.0 && options->rate_hz <= 10000.0)) return fail(KUMITE_ERROR_ARGUMENT, "kumite_bout_create: rate_hz must be 1 to 10000");
        if (options->aim != KUMITE_AIM_LATCHED && options->aim != KUMITE_AIM_PREDICTED) return fail(KUMITE_ERROR_ARGUMENT, "kumite_bout_create: aim must be a kumite_aim");
        const std::filesystem::path folder = options->characters_dir ? std::filesystem::path(options->characters_dir) : kumite::default_characters_dir();
        kumite::Result<kumite::BoutCast> cast = kumite::load_bout_cast(folder, options->character ? options->character : "");
        if (!cast) return status_of(cast.error());
        std::unique_ptr<kumite::HeadTracker> tracker;
        if (options->tracker) {
            kumite::Result<std::unique_ptr<kumite::HeadTracker>> opened = kumite::HeadTracker::open(options->tracker, kumite::DtrackConfig{}, options->seed);
            if (!opened) return status_of(opened.error());
            tracker = std::move(*opened);
        } else {
            tracker = kumite::HeadTracker::fed();
        }
        kumite::BoutOptions bout_options;
        bout_options.fighters = options->fighters;
        bout_options.start_character = cast->start;
        bout_options.rate_hz = options->rate_hz;
        bout_options.fighter.aim = options->aim == KUMITE_AIM_PREDICTED ? kumite::FighterAim::predicted : kumite::FighterAim::latched;
        bout_options.fighter.defence.enabled = options->defence != 0;
        int most_joints = 0;
        for (const kumite::BoutCharacter& character : cast->characters) most_joints = std::max(most_joints, character.file.clip.skeleton.joint_count());
        kumite::Result<std::unique_ptr<kumite::Bout>> created =
            kumite::Bout::create(database->database.view(), std::move(cast->characters), std::move(tracker), bout_options);
        if (!created) return status_of(created.error());
        auto made = std::make_unique<kumite_bout>();
        made->bout = std::move(*created);
        made->fed = options->tracker == nullptr;
        made->skin.resize(std::size_t(most_joints));
        *bout = made.release();
        return KUMITE_OK;
    });
}

void kumite_bout_destroy(kumite_bout* bout) { delete bout; }

kumite_status kumite_bout_set_user(kumite_bout* bout, const double head[3], const double left_hand[3], const double right_hand[3]) {
    return guarded("kumite_bout_set_user", [&] {
        if (!bout) return fail(KUMITE_ERROR_ARGUMENT, "kumite_bout_set_user: bout is NULL");
        if (!bout->fed) return fail(KUMITE_ERROR_INVALID, "kumite_bout_set_user: this bout's user comes from its tracker (options.tracker was set)");
        kumite::UserHands hands;
        const double* given[2] = {left_hand, right_hand};
        for (int side = 0; side < 2; ++side) {
            if (!given[side]) continue;
            const Eigen::Vector3d point(given[side][0], given[side][1], given[side][2]);
            if (!point.allFinite()) return fail(KUMITE_ERROR_ARGUMENT, std::string("kumite_bout_set_user: the ") + (side ? "right" : "left") + " hand is not finite");
            hands.present[std::size_t(side)] = true;
            hands.world[std::size_t(side)] = point;
        }
        if (!head) {
            bout->bout->tracker().feed(nullptr, hands);
            return KUMITE_OK;
        }
        const Eigen::Vector3d point(head[0], head[1], head[2]);
        if (!point.allFinite()) return fail(KUMITE_ERROR_ARGUMENT, "kumite_bout_set_user: the head is not finite");
        bout->bout->tracker().feed(&point, hands);
        return KUMITE_OK;
    });
}

kumite_status kumite_bout_command(kumite_bout* bout, const char* line) {
    return guarded("kumite_bout_command", [&] {
        if (!bout || !line) return fail(KUMITE_ERROR_ARGUMENT, "kumite_bout_command: bout and line must not be NULL");
        kumite::Result<void> taken = bout->bout->command(line);
        if (!taken) return status_of(taken.error());
        return KUMITE_OK;
    });
}

kumite_status kumite_bout_step(kumite_bout* bout, double t_s) {
    return guarded("kumite_bout_step", [&] {
        if (!bout) return fail(KUMITE_ERROR_ARGUMENT, "kumite_bout_step: bout is NULL");
        if (!std::isfinite(t_s)) return fail(KUMITE_ERROR_ARGUMENT, "kumite_bout_step: t_s is not finite");
        bout->bout->step(t_s);
        bout->next_event = 0;
        return KUMITE_OK;
    });
}

int kumite_bout_fighter_count(const kumite_bout* bout) { return bout ? bout->bout->fighter_count() : -1; }

int kumite_bout_joint_count(const kumite_bout* bout, int fighter) {
    const kumite::Fighter* f = fighter_of(bout, fighter);
    return f ? bout->bout->character_skeleton(f->character()).joint_count() : -1;
}

const char* kumite_bout_joint_name(const kumite_bout* bout, int fighter, int joint) {
    const kumite::Fighter* f = fighter_of(bout, fighter);
    if (!f) return nullptr;
    const kumite::Skeleton& skeleton = bout->bout->character_skeleton(f->character());
    return joint >= 0 && joint < skeleton.joint_count() ? skeleton.names[std::size_t(joint)].c_str() : nullptr;
}

kumite_status kumite_bout_joint_parents(const kumite_bout* bout, int fighter, int32_t* parents, size_t count) {
    if (kumite_status status = check_fighter(bout, fighter, "kumite_bout_joint_parents"); status != KUMITE_OK) return status;
    const kumite::Skeleton& skeleton = bout->bout->character_skeleton(fighter_of(bout, fighter)->character());
    if (kumite_status status = check_buffer(parents, count, std::size_t(skeleton.joint_count()), "kumite_bout_joint_parents"); status != KUMITE_OK) return status;
    for (int j = 0; j < skeleton.joint_count(); ++j) parents[j] = skeleton.parents[std::size_t(j)];
    return KUMITE_OK;
}

kumite_status kumite_bout_world_transforms(const kumite_bout* bout, int fighter, float* matrices, size_t count) {
    if (kumite_status status = check_fighter(bout, fighter, "kumite_bout_world_transforms"); status != KUMITE_OK) return status;
    const kumite::Fighter& f = *fighter_of(bout, fighter);
    const std::span<const Eigen::Vector3d> positions = f.positions();
    const std::span<const Eigen::Quaterniond> rotations = f.rotations();
    if (kumite_status status = check_buffer(matrices, count, 16 * positions.size(), "kumite_bout_world_transforms"); status != KUMITE_OK) return status;
    for (std::size_t j = 0; j < positions.size(); ++j) {
        Eigen::Matrix4f matrix = Eigen::Matrix4f::Identity();
        matrix.topLeftCorner<3, 3>() = rotations[j].toRotationMatrix().cast<float>();
        matrix.topRightCorner<3, 1>() = positions[j].cast<float>();
        store_matrix(matrices + 16 * j, matrix);
    }
    return KUMITE_OK;
}

int kumite_bout_has_body(const kumite_bout* bout, int fighter) {
    const kumite::Fighter* f = fighter_of(bout, fighter);
    return f && bout->bout->character_body(f->character()) ? 1 : 0;
}

kumite_status kumite_bout_skin_matrices(const kumite_bout* bout, int fighter, float* matrices, size_t count) {
    if (kumite_status status = check_fighter(bout, fighter, "kumite_bout_skin_matrices"); status != KUMITE_OK) return status;
    const kumite::Fighter& f = *fighter_of(bout, fighter);
    const std::shared_ptr<const kumite::SkinnedMesh>& body = bout->bout->character_body(f.character());
    if (!body) return fail(KUMITE_ERROR_INVALID, "kumite_bout_skin_matrices: the character '" + bout->bout->character_name(f.character()) + "' has no body");
    const std::span<const Eigen::Vector3d> positions = f.positions();
    if (kumite_status status = check_buffer(matrices, count, 16 * positions.size(), "kumite_bout_skin_matrices"); status != KUMITE_OK) return status;
    // The bout's own scratch (sized at creation): no allocation. A bout is used by one thread at a time.
    std::span<Eigen::Matrix4f> skin(const_cast<kumite_bout*>(bout)->skin.data(), positions.size());
    kumite::skin_matrices(skin, *body, positions, f.rotations());
    for (std::size_t j = 0; j < positions.size(); ++j) store_matrix(matrices + 16 * j, skin[j]);
    return KUMITE_OK;
}

int kumite_bout_next_event(kumite_bout* bout, char* buffer, size_t capacity, size_t* length) {
    bool wrote = false;
    kumite_status status = guarded("kumite_bout_next_event", [&] {
        if (!bout) return fail(KUMITE_ERROR_ARGUMENT, "kumite_bout_next_event: bout is NULL");
        const std::span<const kumite::BoutEvent> events = bout->bout->events();
        if (bout->next_event >= events.size()) {
            if (length) *length = 0;
            return KUMITE_OK;
        }
        const std::string text = kumite::bout_event_json(*bout->bout, events[bout->next_event]);
        if (length) *length = text.size() + 1;
        if (!buffer || capacity < text.size() + 1) {
            return fail(KUMITE_ERROR_ARGUMENT, "kumite_bout_next_event: the event takes " + std::to_string(text.size() + 1) + " bytes, the buffer holds " +
                                                   std::to_string(buffer ? capacity : 0));
        }
        std::memcpy(buffer, text.c_str(), text.size() + 1);
        ++bout->next_event;
        wrote = true;
        return KUMITE_OK;
    });
    return status != KUMITE_OK ? -1 : wrote ? 1 : 0;
}

} // extern "C"
