#include "kumite/core/motion_database.h"

#include "kumite/core/strike_adaptation.h"

#include <cassert>

namespace kumite {
namespace {

void store_quaternion(float (&out)[4], const Eigen::Quaterniond& q) {
    out[0] = static_cast<float>(q.x());
    out[1] = static_cast<float>(q.y());
    out[2] = static_cast<float>(q.z());
    out[3] = static_cast<float>(q.w());
}

Eigen::Quaterniond load_quaternion(const float (&in)[4]) {
    Eigen::Quaterniond q(in[3], in[0], in[1], in[2]);
    const double norm = q.norm();
    return norm > 1e-12 ? Eigen::Quaterniond(q.coeffs() / norm) : Eigen::Quaterniond::Identity();
}

void store_chain(float (&frames)[k_max_chain_joints][4], float (&fractions)[k_max_chain_joints], std::uint32_t& count,
                 const MirChainFrames& chain) {
    count = static_cast<std::uint32_t>(chain.count);
    for (int k = 0; k < chain.count; ++k) {
        store_quaternion(frames[k], chain.frames[k]);
        fractions[k] = static_cast<float>(chain.fractions[k]);
    }
}

void load_chain(MirChainFrames& chain, const float (&frames)[k_max_chain_joints][4], const float (&fractions)[k_max_chain_joints],
                std::uint32_t count) {
    chain.count = static_cast<int>(std::min<std::uint32_t>(count, k_max_chain_joints));
    for (int k = 0; k < chain.count; ++k) {
        chain.frames[k] = load_quaternion(frames[k]);
        chain.fractions[k] = fractions[k];
    }
}

} // namespace

DbString MotionDatabaseContent::add_string(std::string_view text) {
    DbString reference{static_cast<std::uint32_t>(strings.size()), static_cast<std::uint32_t>(text.size())};
    strings.insert(strings.end(), text.begin(), text.end());
    return reference;
}

MotionDatabaseView MotionDatabaseContent::view() const {
    MotionDatabaseView view;
    view.meta = meta;
    view.strings = strings;
    view.actors = actors;
    view.clips = clips;
    view.poses = poses;
    view.mir_frames = mir_frames;
    view.features = features;
    view.centroids = centroids;
    view.clusters = clusters;
    view.members = members;
    return view;
}

void db_mir_frame_store(DbMirFrame& out, const MirFrame& frame) {
    out = DbMirFrame{};
    for (int axis = 0; axis < 3; ++axis) out.hip_centre[axis] = static_cast<float>(frame.hip_centre[axis]);
    for (int part = 0; part < k_body_part_count; ++part) {
        if (frame.has_part[part]) out.part_mask |= 1u << part;
        store_quaternion(out.part_frames[part], frame.part_frames[part]);
    }
    store_chain(out.spine, out.spine_fractions, out.spine_count, frame.spine);
    store_chain(out.neck, out.neck_fractions, out.neck_count, frame.neck);
    for (int limb = 0; limb < k_limb_count; ++limb) {
        for (int axis = 0; axis < 3; ++axis) out.extremity[limb][axis] = static_cast<float>(frame.extremity[limb][axis]);
        out.swivel[limb] = static_cast<float>(frame.swivel[limb]);
    }
}

int db_first_clip_of(const MotionDatabaseView& db, std::string_view semantics) {
    for (std::size_t c = 0; c < db.clips.size(); ++c) {
        if (db.string(db.clips[c].semantics) == semantics) return static_cast<int>(c);
    }
    return -1;
}

int db_clip_contact_frame(const MotionDatabaseView& db, const DbClip& clip, double extension, double speed_share) {
    if (!db_clip_is_strike(clip) || clip.hit_frame < 0) return -1;
    if (extension >= 1.0) return clip.hit_frame;
    auto hit_point = [&](int frame) {
        const float* p = db.poses[clip.first_pose + frame].hit_point;
        return Eigen::Vector3d(p[0], p[1], p[2]);
    };
    const Eigen::Vector3d at_hit = hit_point(clip.hit_frame);
    int farthest_frame = 0;
    double farthest = 0.0;
    for (int f = 0; f <= clip.hit_frame; ++f) {
        const double distance = (hit_point(f) - at_hit).norm();
        if (distance > farthest) farthest = distance, farthest_frame = f;
    }
    int contact = clip.hit_frame;
    for (int f = farthest_frame; f <= clip.hit_frame; ++f) {
        if ((hit_point(f) - at_hit).norm() <= (1.0 - extension) * farthest) {
            contact = f;
            break;
        }
    }
    const bool strikes_with_middle = clip.segment >= 0 && clip.segment < k_body_part_count && segment_strikes_with_middle(static_cast<BodyPart>(clip.segment));
    if (speed_share > 0.0 && contact > farthest_frame && !strikes_with_middle) {
        // The step into each frame (per frame: the rate is the clip's), its fastest on the way from the farthest.
        auto step = [&](int f) { return (hit_point(f) - hit_point(f - 1)).norm(); };
        int fastest_frame = farthest_frame + 1;
        for (int f = farthest_frame + 1; f <= contact; ++f) {
            if (step(f) > step(fastest_frame)) fastest_frame = f;
        }
        const double fast = speed_share * step(fastest_frame);
        for (int f = fastest_frame + 1; f <= contact; ++f) {
            if (step(f) < fast) return f - 1;
        }
    }
    return contact;
}

void db_mir_frame_load(MirFrame& out, const DbMirFrame& stored) {
    out.hip_centre = Eigen::Vector3d(stored.hip_centre[0], stored.hip_centre[1], stored.hip_centre[2]);
    for (int part = 0; part < k_body_part_count; ++part) {
        out.has_part[part] = (stored.part_mask >> part) & 1u;
        out.part_frames[part] = load_quaternion(stored.part_frames[part]);
    }
    load_chain(out.spine, stored.spine, stored.spine_fractions, stored.spine_count);
    load_chain(out.neck, stored.neck, stored.neck_fractions, stored.neck_count);
    for (int limb = 0; limb < k_limb_count; ++limb) {
        out.extremity[limb] = Eigen::Vector3d(stored.extremity[limb][0], stored.extremity[limb][1], stored.extremity[limb][2]);
        out.swivel[limb] = stored.swivel[limb];
    }
    out.source_local_rotations.clear(); // keeps capacity: no allocation
}

bool db_clip_is_strike(const DbClip& clip) { return (clip.flags & db_clip_strike) != 0; }

bool db_clip_is_arm_strike(const DbClip& clip) {
    return db_clip_is_strike(clip) && clip.segment >= static_cast<int>(BodyPart::clavicle_l) &&
           clip.segment <= static_cast<int>(BodyPart::hand_r);
}

std::uint32_t db_clip_support_foot(const DbClip& clip) {
    if (!db_clip_is_strike(clip) || db_clip_is_arm_strike(clip)) return 0;
    const bool left_leg = body_part_name(static_cast<BodyPart>(clip.segment)).ends_with("_l");
    return left_leg ? db_pose_right_foot_planted : db_pose_left_foot_planted;
}

int db_clip_support_down_until(const MotionDatabaseView& db, const DbClip& clip) {
    const std::uint32_t support = db_clip_support_foot(clip);
    if (!support) return -1;
    for (int frame = clip.hit_frame; frame >= 0; --frame) {
        if (db.poses[clip.first_pose + frame].flags & support) return frame;
    }
    return -1;
}

} // namespace kumite
