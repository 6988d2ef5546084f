#include "kumite/formats/motion_database_file.h"

#include "motion_database_checker.h"

#include <type_traits>

namespace kumite {
namespace {

static_assert(sizeof(DbMeta) == 32 && sizeof(DbActor) == 24 && sizeof(DbClip) == 84 && sizeof(DbPose) == 60 &&
                  sizeof(DbCluster) == 16 && sizeof(DbMirFrame) == 4 * (4 + 4 * k_body_part_count + 10 * k_max_chain_joints + 2 + 4 * k_limb_count),
              "records have no padding: their bytes are the file's bytes");
static_assert(std::is_trivially_copyable_v<DbMirFrame> && std::is_trivially_copyable_v<DbClip>);

template <class T>
void add(DatabaseImageBuilder& builder, std::uint32_t tag, std::span<const T> items) {
    builder.add_section(tag, sizeof(T), std::as_bytes(items));
}

DatabaseImageBuilder image_builder(const MotionDatabaseView& db) {
    DatabaseImageBuilder builder;
    add(builder, k_section_meta, std::span<const DbMeta>(&db.meta, 1));
    add(builder, k_section_strings, db.strings);
    add(builder, k_section_actors, db.actors);
    add(builder, k_section_clips, db.clips);
    add(builder, k_section_poses, db.poses);
    add(builder, k_section_mir_frames, db.mir_frames);
    add(builder, k_section_features, db.features);
    add(builder, k_section_centroids, db.centroids);
    add(builder, k_section_clusters, db.clusters);
    add(builder, k_section_members, db.members);
    return builder;
}

} // namespace

std::vector<std::byte> motion_database_bytes(const MotionDatabaseView& db) { return image_builder(db).build(); }

Result<void> motion_database_write(const std::filesystem::path& path, const MotionDatabaseView& db) {
    return image_builder(db).write_file(path);
}

Result<MotionDatabase> MotionDatabase::open(const std::filesystem::path& path, bool verify) {
    Result<DatabaseImage> image = DatabaseImage::open(path);
    if (!image) return image.error();
    Result<MotionDatabase> database = from_image(std::move(*image), path.string());
    if (!database || !verify) return database;
    if (Result<void> verified = database->verify(); !verified) return verified.error();
    return database;
}

Result<MotionDatabase> MotionDatabase::from_image(DatabaseImage image, std::string_view source_name) {
    using database_checks::Checker;
    MotionDatabase database;
    database.m_image = std::move(image);
    database.m_source_name = source_name;
    const Checker check(database.m_source_name, database.m_image);
    MotionDatabaseView& view = database.m_view;
    auto meta = check.records<DbMeta>(k_section_meta);
    if (!meta) return meta.error();
    if (meta->size() != 1) return check.fail_at<DbMeta>(k_section_meta, 0, "expected one META record, found " + std::to_string(meta->size()));
    view.meta = (*meta)[0];
    auto load = [&]<class T>(std::span<const T>& out, std::uint32_t tag) -> std::optional<Error> {
        auto records = check.records<T>(tag);
        if (!records) return records.error();
        out = *records;
        return std::nullopt;
    };
    if (auto e = load(view.strings, k_section_strings)) return *e;
    if (auto e = load(view.actors, k_section_actors)) return *e;
    if (auto e = load(view.clips, k_section_clips)) return *e;
    if (auto e = load(view.poses, k_section_poses)) return *e;
    if (auto e = load(view.mir_frames, k_section_mir_frames)) return *e;
    if (auto e = load(view.features, k_section_features)) return *e;
    if (auto e = load(view.centroids, k_section_centroids)) return *e;
    if (auto e = load(view.clusters, k_section_clusters)) return *e;
    if (auto e = load(view.members, k_section_members)) return *e;
    if (Result<void> structure = database_checks::check_structure(view, check); !structure) return structure.error();
    return database;
}

Result<void> MotionDatabase::verify_values() const {
    return database_checks::check_values(m_view, database_checks::Checker(m_source_name, m_image));
}

Result<void> MotionDatabase::verify() const {
    if (Result<void> values = verify_values(); !values) return values;
    return m_image.verify_hash();
}

} // namespace kumite
