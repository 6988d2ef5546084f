#include "exr_export.h"

#include "parallel_for.h"

#include "kumite/core/pose_features.h"

#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFloatAttribute.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfOutputFile.h>
#include <OpenEXR/ImfStringVectorAttribute.h>

#include <chrono>
#include <mutex>

namespace kumite::bake {
namespace {

struct ExrImage {
    int width = 0;
    int height = 0;
    std::vector<const char*> channels; // FLOAT channels, interleaved in `pixels`
    std::vector<float> pixels;         // [row][column][channel]
};

// Writes through a temporary beside the target, then renames.
Result<void> write_exr(const std::filesystem::path& path, const ExrImage& image, const std::function<void(Imf::Header&)>& add_attributes) {
    const std::filesystem::path temporary = path.string() + ".partial";
    try {
        Imf::Header header(image.width, image.height);
        header.compression() = Imf::ZIP_COMPRESSION;
        for (const char* channel : image.channels) header.channels().insert(channel, Imf::Channel(Imf::FLOAT));
        add_attributes(header);
        Imf::FrameBuffer buffer;
        const std::size_t pixel_bytes = sizeof(float) * image.channels.size();
        for (std::size_t c = 0; c < image.channels.size(); ++c) {
            char* base = reinterpret_cast<char*>(const_cast<float*>(image.pixels.data() + c));
            buffer.insert(image.channels[c], Imf::Slice(Imf::FLOAT, base, pixel_bytes, pixel_bytes * image.width));
        }
        Imf::OutputFile file(temporary.c_str(), header);
        file.setFrameBuffer(buffer);
        file.writePixels(image.height);
    } catch (const std::exception& error) {
        std::error_code ignored;
        std::filesystem::remove(temporary, ignored);
        return make_error(ErrorCode::io, path.string() + ": cannot write the EXR file: " + error.what());
    }
    std::error_code error;
    std::filesystem::rename(temporary, path, error);
    if (error) return make_error(ErrorCode::io, path.string() + ": cannot rename the finished EXR file: " + error.message());
    return {};
}

std::string safe_file_part(std::string_view name) {
    std::string out;
    for (char c : name) out += (std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '_') ? c : '_';
    return out.substr(0, 80);
}

ExrImage distance_matrix(const MotionDatabaseContent& db, int jobs, const std::function<void(int, int)>& on_row) {
    const int n = static_cast<int>(db.poses.size());
    ExrImage image{n, n, {"Y"}, std::vector<float>(std::size_t(n) * n)};
    const MotionDatabaseView view = db.view();
    std::mutex mutex;
    int rows_done = 0;
    parallel_for(n, jobs, [&](int i) {
        for (int j = i; j < n; ++j) {
            const float d = static_cast<float>(pose_feature_distance(view.feature(i), view.feature(j)));
            image.pixels[std::size_t(i) * n + j] = d;
            image.pixels[std::size_t(j) * n + i] = d;
        }
        std::lock_guard lock(mutex);
        on_row(++rows_done, n);
    });
    return image;
}

ExrImage animation_texture(const Clip& clip) {
    const int joints = clip.skeleton.joint_count();
    ExrImage image{joints + 1, clip.frame_count(), {"R", "G", "B", "A"}, {}};
    image.pixels.reserve(std::size_t(image.width) * image.height * 4);
    for (int frame = 0; frame < clip.frame_count(); ++frame) {
        const PoseView pose = clip.pose(frame);
        const Eigen::Vector3d& t = pose.root_translation;
        image.pixels.insert(image.pixels.end(), {float(t.x()), float(t.y()), float(t.z()), 0.0f});
        for (const Eigen::Quaterniond& q : pose.local_rotations) {
            image.pixels.insert(image.pixels.end(), {float(q.x()), float(q.y()), float(q.z()), float(q.w())});
        }
    }
    return image;
}

} // namespace

Result<ExrExportSummary> exr_export(const std::filesystem::path& folder, const BakeResult& baked, int jobs,
                                    const std::function<void(const BakeProgress&)>& progress) {
    const auto started = std::chrono::steady_clock::now();
    std::error_code error;
    std::filesystem::create_directories(folder, error);
    if (error) return make_error(ErrorCode::io, folder.string() + ": cannot create the EXR folder: " + error.message());
    const MotionDatabaseContent& db = baked.database;
    const MotionDatabaseView view = db.view();
    ExrExportSummary summary;

    const ExrImage matrix = distance_matrix(db, jobs, [&](int done, int total) {
        if (progress && (done % 64 == 0 || done == total)) progress({"pose distances", done, total});
    });
    std::vector<std::string> clip_lines;
    for (const DbClip& clip : db.clips) {
        clip_lines.push_back(std::string(view.string(clip.name)) + " " + std::to_string(clip.first_pose) + " " + std::to_string(clip.frame_count));
    }
    summary.files.push_back(folder / "pose_distance.exr");
    if (Result<void> written = write_exr(summary.files.back(), matrix,
                                         [&](Imf::Header& header) { header.insert("kumite:clips", Imf::StringVectorAttribute(clip_lines)); });
        !written) {
        return written.error();
    }

    for (std::size_t index = 0; index < baked.motions.size(); ++index) {
        const BakedMotion& motion = baked.motions[index];
        const Skeleton& skeleton = motion.clip.skeleton;
        std::vector<std::string> parents;
        for (int joint = 0; joint < skeleton.joint_count(); ++joint) {
            parents.push_back(skeleton.parents[joint] >= 0 ? skeleton.names[skeleton.parents[joint]] : "");
        }
        char prefix[32];
        std::snprintf(prefix, sizeof prefix, "clip_%03zu_", index);
        summary.files.push_back(folder / (prefix + safe_file_part(motion.clip_name) + ".exr"));
        Result<void> written = write_exr(summary.files.back(), animation_texture(motion.clip), [&](Imf::Header& header) {
            header.insert("kumite:joints", Imf::StringVectorAttribute(skeleton.names));
            header.insert("kumite:parents", Imf::StringVectorAttribute(parents));
            header.insert("kumite:frame_time_s", Imf::FloatAttribute(static_cast<float>(motion.clip.frame_time_s)));
        });
        if (!written) return written.error();
        if (progress) progress({"animation textures", static_cast<int>(index + 1), static_cast<int>(baked.motions.size())});
    }
    summary.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
    return summary;
}

} // namespace kumite::bake
