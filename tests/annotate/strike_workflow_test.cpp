// The animator's path on the Bandai kick capture, without the window: accept the three right-kick suggestions,
// check what the viewport draws (trajectory, contact, box), save, bake with the window's code and with
// `kumite bake`, and read the heatmap of the database.

#include "annotation_document.h"
#include "bake.h"
#include "clip_trajectory.h"
#include "pose_heatmap.h"
#include "qt_application.h"
#include "support/test_paths.h"

#include "kumite/core/forward_kinematics.h"
#include "kumite/formats/motion_database_file.h"

#include <catch2/catch.hpp>

#include <fstream>
#include <iterator>

using namespace kumite;
using namespace kumite::annotate;

namespace {

const std::string k_kick_capture = "bandai-namco-1/dataset-1_kick_normal_001.bvh";

// The document after accepting every right-foot kick suggestion of the kick capture.
void accept_right_kicks(AnnotationDocument& document) {
    REQUIRE(document.open_capture(QString::fromStdString((test::mocap_root() / k_kick_capture).string())));
    const LoadedCapture* capture = document.current_capture();
    REQUIRE(capture);
    for (const StrikeSuggestion& strike : capture->suggestions) {
        if (strike.semantics == StrikeSemantics::kick && strike.segment == BodyPart::foot_r) {
            document.add_suggestion(strike, capture->source);
        }
    }
}

} // namespace

TEST_CASE("strike workflow: the kick capture's suggestions give its three right kicks as clips", "[annotate]") {
    test::qt_application();
    if (!std::filesystem::exists(test::mocap_root() / k_kick_capture)) { WARN("captures absent: skipped"); return; }
    AnnotationDocument document(test::mocap_root());
    accept_right_kicks(document);
    REQUIRE(document.clip_count() == 3);
    // The reference file's kicks (data/annotations/reference.json) were made from the same suggestions.
    Result<RawAnnotations> reference = annotations_read_file(test::source_dir() / "data/annotations/reference.json");
    REQUIRE(reference);
    for (int index = 0; index < 3; ++index) {
        const RawAnnotatedClip& clip = document.clip(index);
        CHECK(clip.source == k_kick_capture); // relative to the mocap root, as bake resolves it
        CHECK(clip.semantics == "kick");
        CHECK(clip.side == Side::right);
        CHECK(document.clip_messages(index).empty());
        // The reference may predate the kind and height labels (format version 1): then only the rest must agree.
        RawAnnotatedClip unlabelled = clip;
        unlabelled.kind = StrikeKind::none;
        unlabelled.height = StrikeHeight::none;
        bool in_reference = false;
        for (const RawAnnotatedClip& known : reference->clips) {
            const bool labelled = known.kind != StrikeKind::none || known.height != StrikeHeight::none;
            in_reference |= clips_equal(known, labelled ? clip : unlabelled);
        }
        CHECK(in_reference);
    }
    CHECK(document.undo_stack()->count() == 3);
    CHECK(document.undo_stack()->undoText() == "Accept Suggestion");
}

TEST_CASE("strike workflow: the trajectory passes through the hit joint and the box holds the path to the hit", "[annotate]") {
    test::qt_application();
    if (!std::filesystem::exists(test::mocap_root() / k_kick_capture)) { WARN("captures absent: skipped"); return; }
    AnnotationDocument document(test::mocap_root());
    accept_right_kicks(document);
    REQUIRE(document.clip_count() == 3);
    const RawAnnotatedClip& clip = document.clip(1);
    const LoadedCapture* capture = document.capture_of(1);
    REQUIRE(capture);
    Result<ClipTrajectory> trajectory = clip_trajectory_compute(*capture, clip.semantics, *clip.segment, clip.first_frame, *clip.hit_frame, clip.last_frame);
    REQUIRE(trajectory);
    REQUIRE(int(trajectory->points_world.size()) == clip.last_frame - clip.first_frame + 1);

    const Skeleton& skeleton = capture->file.clip.skeleton;
    std::vector<Eigen::Vector3d> positions(size_t(skeleton.joint_count()));
    std::vector<Eigen::Quaterniond> rotations(size_t(skeleton.joint_count()));
    forward_kinematics(positions, rotations, skeleton, capture->file.clip.pose(*clip.hit_frame));
    const int foot = capture->file.body_map.joint(BodyPart::foot_r);
    CHECK((trajectory->contact_world - positions[size_t(foot)]).norm() < 1e-9);

    // Every point from the first frame to the hit lies in the world box (its corners span it in the first heading).
    const Eigen::Vector3d origin = trajectory->box_corners_world[0];
    const Eigen::Vector3d axis_x = trajectory->box_corners_world[1] - origin;
    const Eigen::Vector3d axis_y = trajectory->box_corners_world[2] - origin;
    const Eigen::Vector3d axis_z = trajectory->box_corners_world[4] - origin;
    CHECK(axis_x.dot(axis_z) == Approx(0.0).margin(1e-9));
    for (int frame = clip.first_frame; frame <= *clip.hit_frame; ++frame) {
        const Eigen::Vector3d offset = trajectory->points_world[size_t(frame - clip.first_frame)] - origin;
        for (const Eigen::Vector3d& axis : {axis_x, axis_y, axis_z}) {
            const double along = offset.dot(axis) / std::max(axis.squaredNorm(), 1e-12);
            CHECK(along >= -1e-6);
            CHECK(along <= 1.0 + 1e-6);
        }
    }
    CHECK_FALSE(clip_trajectory_compute(*capture, "kick", BodyPart::foot_r, 50, 40, 60)); // hit before the in point
}

TEST_CASE("strike workflow: the saved file bakes with `kumite bake`, the window's bake gives the same database", "[annotate]") {
    test::qt_application();
    if (!std::filesystem::exists(test::mocap_root() / k_kick_capture)) { WARN("captures absent: skipped"); return; }
    const std::filesystem::path folder = test::make_temp_dir("annotate-bake");
    AnnotationDocument document(test::mocap_root());
    accept_right_kicks(document);
    const std::filesystem::path saved = folder / "kicks.json";
    REQUIRE(document.save_as(QString::fromStdString(saved.string())));

    // Byte for byte what `kumite suggest --write-annotations` writes for the same capture (its 3 strikes).
    const test::CommandOutput suggest = test::run_command((test::bin_dir() / "kumite").string() + " suggest " + k_kick_capture +
                                                          " --mocap-root " + test::mocap_root().string() + " --write-annotations " +
                                                          (folder / "suggested.json").string());
    REQUIRE(suggest.status == 0);
    CHECK(document.text() == annotations_write_string(annotations_read_file(folder / "suggested.json").value()));
    std::ifstream suggested_stream(folder / "suggested.json", std::ios::binary), saved_stream(saved, std::ios::binary);
    const std::string suggested_text((std::istreambuf_iterator<char>(suggested_stream)), std::istreambuf_iterator<char>());
    const std::string saved_text((std::istreambuf_iterator<char>(saved_stream)), std::istreambuf_iterator<char>());
    CHECK(saved_text == suggested_text);

    const test::CommandOutput cli = test::run_command((test::bin_dir() / "kumite").string() + " bake " + saved.string() + " -o " +
                                                      (folder / "cli.kdb").string() + " --mocap-root " + test::mocap_root().string());
    INFO(cli.err);
    REQUIRE(cli.status == 0);

    bake::BakeOptions options;
    options.mocap_root = test::mocap_root();
    Result<bake::BakeResult> baked = bake::bake_database(document.annotations(), saved.string(), options);
    REQUIRE(baked);
    CHECK(motion_database_bytes(baked->database.view()) ==
          motion_database_bytes(MotionDatabase::open(folder / "cli.kdb").value().view()));
    const MotionDatabaseView view = baked->database.view();
    CHECK(view.clips.size() == 6); // three kicks and their mirrors

    const PoseHeatmap clusters = pose_heatmap_of_clusters(view);
    REQUIRE(clusters.rows == int(view.clusters.size()));
    REQUIRE(clusters.columns == clusters.rows);
    CHECK(clusters.max_distance > 0.0f);
    for (int row = 0; row < clusters.rows; ++row) {
        CHECK(clusters.at(row, row) == 0.0f);
        for (int column = 0; column < row; ++column) CHECK(clusters.at(row, column) == clusters.at(column, row));
        // A row's pose is a member of its cluster, and it leads back to a clip of the file.
        const DbCluster& cluster = view.clusters[size_t(row)];
        const auto members = view.members.subspan(cluster.first_member, cluster.member_count);
        CHECK(std::find(members.begin(), members.end(), clusters.row_poses[size_t(row)]) != members.end());
        CHECK(clusters.column_poses[size_t(row)] == clusters.row_poses[size_t(row)]);
        const PoseLocation location = pose_location(view, clusters.row_poses[size_t(row)]);
        CHECK(document.find_clip(location.clip_name) >= 0);
    }
    const PoseHeatmap poses = pose_heatmap_of_poses(view, 50);
    CHECK(poses.rows > 0);
    CHECK(poses.rows <= 50);
    CHECK(poses.columns == poses.rows);

    // One clip's poses against the clusters: a row per baked frame, and each pose's own cluster is among the
    // nearest centroids (k-means assigns it to the nearest one when it converged).
    const std::string name = document.clip(1).name;
    const PoseHeatmap clip = pose_heatmap_of_clip(view, name);
    const auto baked_clip = std::find_if(view.clips.begin(), view.clips.end(), [&](const DbClip& c) { return view.string(c.name) == name; });
    REQUIRE(baked_clip != view.clips.end());
    REQUIRE(clip.rows == int(baked_clip->frame_count));
    REQUIRE(clip.columns == int(view.clusters.size()));
    int nearest_is_own = 0;
    for (int row = 0; row < clip.rows; ++row) {
        CHECK(clip.row_poses[size_t(row)] == baked_clip->first_pose + std::uint32_t(row));
        CHECK(pose_location(view, clip.row_poses[size_t(row)]).clip_name == name);
        int nearest = 0;
        for (int column = 1; column < clip.columns; ++column) nearest = clip.at(row, column) < clip.at(row, nearest) ? column : nearest;
        const DbCluster& own = view.clusters[size_t(nearest)];
        const auto members = view.members.subspan(own.first_member, own.member_count);
        nearest_is_own += std::find(members.begin(), members.end(), clip.row_poses[size_t(row)]) != members.end();
    }
    CHECK(nearest_is_own >= clip.rows * 9 / 10);
    CHECK(pose_heatmap_of_clip(view, "no such clip").rows == 0);
}

TEST_CASE("strike workflow: a hand-trimmed kick gets its hit frame proposed at the foot's peak", "[annotate]") {
    test::qt_application();
    if (!std::filesystem::exists(test::mocap_root() / k_kick_capture)) { WARN("captures absent: skipped"); return; }
    AnnotationDocument document(test::mocap_root());
    REQUIRE(document.open_capture(QString::fromStdString((test::mocap_root() / k_kick_capture).string())));
    const LoadedCapture& capture = *document.current_capture();
    // The reference file's second kick was confirmed at 194 (data/annotations/reference.json).
    const std::optional<int> kick = hit_frame_suggest(capture, BodyPart::foot_r, 150, 230);
    REQUIRE(kick);
    CHECK(*kick == 194);
    // No kick of the left foot there: its own extension peak, inside the range, or none.
    const std::optional<int> left = hit_frame_suggest(capture, BodyPart::foot_l, 150, 230);
    if (left) CHECK((*left >= 150 && *left <= 230));
    CHECK_FALSE(hit_frame_suggest(capture, BodyPart::foot_r, 100, 120)); // the foot stays down there
}
