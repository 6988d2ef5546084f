// The reference for c_api_threads_test.c: the bout through the C++ API, summarised the same way.

#include "reference_bout.h"

#include "kumite/formats/character_catalog.h"
#include "kumite/formats/motion_database_file.h"
#include "kumite/runtime/bout.h"
#include "kumite/runtime/bout_cast.h"
#include "kumite/runtime/bout_event_json.h"

#include <cstring>

extern "C" uint64_t fnv1a(uint64_t hash, const char* text) {
    for (const char* c = text; *c; ++c) hash = (hash ^ static_cast<unsigned char>(*c)) * 1099511628211ULL;
    return hash;
}

extern "C" const char* reference_order(uint64_t seed, int frame) {
    static const char* const orders[] = {"punch", "kick", "punch left hook", "kick right", "knee", "elbow"};
    const int offset = int(seed % 30);
    if (frame < offset || (frame - offset) % 50 != 0) return nullptr;
    return orders[(seed + std::uint64_t(frame)) % 6];
}

extern "C" int reference_bout(const char* database_path, const char* characters_dir, uint64_t seed, bout_summary* summary) {
    *summary = bout_summary{};
    summary->events_hash = 14695981039346656037ULL;
    kumite::Result<kumite::MotionDatabase> database = kumite::MotionDatabase::open(database_path);
    if (!database) return 1;
    kumite::Result<kumite::BoutCast> cast = kumite::load_bout_cast(characters_dir, "brawler");
    if (!cast) return 2;
    kumite::Result<std::unique_ptr<kumite::HeadTracker>> tracker = kumite::HeadTracker::open("simulate:wander", {}, seed);
    if (!tracker) return 3;
    kumite::BoutOptions options;
    options.start_character = cast->start;
    kumite::Result<std::unique_ptr<kumite::Bout>> bout = kumite::Bout::create(database->view(), std::move(cast->characters), std::move(*tracker), options);
    if (!bout) return 4;
    for (int frame = 0; frame < k_reference_frames; ++frame) {
        if (const char* order = reference_order(seed, frame); order && !(*bout)->command(order)) return 5;
        (*bout)->step(frame / 60.0);
        for (const kumite::BoutEvent& event : (*bout)->events()) {
            const std::string text = kumite::bout_event_json(**bout, event);
            summary->events_hash = fnv1a(summary->events_hash, text.c_str());
            ++summary->events;
            summary->strikes += event.event.type == kumite::FighterEvent::Type::strike;
        }
        const kumite::Fighter& fighter = (*bout)->fighter(0);
        for (std::size_t j = 0; j < fighter.positions().size(); ++j) {
            Eigen::Matrix4f matrix = Eigen::Matrix4f::Identity();
            matrix.topLeftCorner<3, 3>() = fighter.rotations()[j].toRotationMatrix().cast<float>();
            matrix.topRightCorner<3, 1>() = fighter.positions()[j].cast<float>();
            for (int i = 0; i < 16; ++i) summary->transform_sum += matrix.data()[i];
            if (j == 0) std::memcpy(summary->last_root, matrix.data(), sizeof summary->last_root);
        }
    }
    return 0;
}
