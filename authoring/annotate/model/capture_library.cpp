#include "capture_library.h"

#include "kumite/formats/capture_file.h"
#include "kumite/formats/character_catalog.h"


namespace kumite::annotate {

std::filesystem::path default_mocap_root() {
    const std::filesystem::path folder = locate_data_folder("KUMITE_MOCAP_ROOT", "data/mocap");
    std::error_code error;
    return folder.is_relative() && std::filesystem::exists(folder, error) ? std::filesystem::absolute(folder, error) : folder;
}

std::optional<int> hit_frame_suggest(const LoadedCapture& capture, BodyPart segment, int first_frame, int last_frame) {
    if (!capture.anatomy) return std::nullopt;
    auto best_in_range = [&](const std::vector<StrikeSuggestion>& strikes) -> std::optional<int> {
        const StrikeSuggestion* best = nullptr;
        for (const StrikeSuggestion& strike : strikes) {
            if (strike.segment != segment || strike.hit_frame < first_frame || strike.hit_frame > last_frame) continue;
            if (!best || strike.confidence > best->confidence) best = &strike;
        }
        return best ? std::optional<int>(best->hit_frame) : std::nullopt;
    };
    if (const std::optional<int> strike = best_in_range(capture.suggestions)) return strike;
    return best_in_range(strikes_detect(capture.file.clip, *capture.anatomy, segment));
}

std::filesystem::path CaptureLibrary::resolve(const std::string& source) const {
    const std::filesystem::path path(source);
    std::error_code error;
    if (path.is_absolute() || std::filesystem::exists(path, error)) return path;
    return m_mocap_root / path;
}

Result<std::unique_ptr<LoadedCapture>> CaptureLibrary::read(const std::filesystem::path& path, const std::string& source,
                                                             std::optional<double> fps) const {
    BvhReadOptions options;
    options.frame_rate_hz = fps;
    Result<BvhFile> file = capture_read_file(path, options);
    if (!file) return file.error();
    auto capture = std::make_unique<LoadedCapture>();
    capture->path = path;
    capture->source = source;
    capture->file = std::move(*file);
    Result<RestAnatomy> anatomy = rest_anatomy_build(capture->file.clip, capture->file.body_map);
    if (anatomy) {
        capture->anatomy = std::move(*anatomy);
        capture->suggestions = strikes_detect(capture->file.clip, *capture->anatomy); // none without a rate
    } else {
        capture->anatomy_error = path.string() + ": " + anatomy.error().message;
    }
    return capture;
}

Result<const LoadedCapture*> CaptureLibrary::load(const std::filesystem::path& path_or_source, std::optional<double> fps) {
    const std::filesystem::path path = resolve(path_or_source.string());
    const std::string source = source_relative_to_root(path, m_mocap_root);
    if (const LoadedCapture* known = find(source)) return known;
    Result<std::unique_ptr<LoadedCapture>> capture = read(path, source, fps);
    if (!capture) return capture.error();
    m_captures.push_back(std::move(*capture));
    return m_captures.back().get();
}

Result<const LoadedCapture*> CaptureLibrary::reload(const std::string& source, std::optional<double> fps) {
    for (const auto& existing : m_captures) {
        if (existing->source != source) continue;
        Result<std::unique_ptr<LoadedCapture>> capture = read(existing->path, source, fps);
        if (!capture) return capture.error();
        *existing = std::move(**capture);
        return existing.get();
    }
    return load(source, fps);
}

const LoadedCapture* CaptureLibrary::find(const std::string& source) const {
    for (const auto& capture : m_captures) {
        if (capture->source == source) return capture.get();
    }
    return nullptr;
}

} // namespace kumite::annotate
