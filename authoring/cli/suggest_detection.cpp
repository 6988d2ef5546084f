// kumite suggest FILE.bvh... --compare ANNOTATIONS.json: how well suggest finds the annotated strikes of whole
// captures. A suggestion matches an annotated strike of the same capture, semantics and side whose hit is within
// 0.25 s of its own, one to one (nearest hits first). Recall: matched / annotated; precision: matched / proposed;
// kind agreement over the matched pairs. Per folder, as the issue asks, with the semantics confusion of
// everything proposed (annotated semantics -> proposed, "none" for a strike missed or a proposal that matches none).
// Strikes (what the fighter is ordered to throw) and blocks (the defence's moves) are also scored apart: a folder
// whose blocks were never annotated (the kata) scores its blocks as extras without changing its strikes' precision.

#include "capture_loading.h"
#include "commands.h"
#include "kumite/core/contact_point.h"
#include "kumite/core/strike_detection.h"
#include "kumite/formats/annotation_file.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <map>
#include <set>

namespace kumite::cli {
namespace {

struct FolderTally {
    int files = 0, annotated = 0, proposed = 0, matched = 0, kinds_compared = 0, kinds_agreed = 0;
    std::map<std::string, std::map<std::string, int>> semantics; // annotated -> proposed -> count
    std::map<std::string, std::map<std::string, int>> kinds;     // of matched pairs
    std::array<std::array<int, 3>, 2> split{};                   // [strikes, blocks][annotated, proposed, matched]
    static nlohmann::json rates(const std::array<int, 3>& counts) {
        return {{"annotated", counts[0]},
                {"proposed", counts[1]},
                {"matched", counts[2]},
                {"recall", counts[0] ? double(counts[2]) / counts[0] : 1.0},
                {"precision", counts[1] ? double(counts[2]) / counts[1] : 1.0}};
    }
    nlohmann::json to_json() const {
        return {{"files", files},
                {"annotated", annotated},
                {"proposed", proposed},
                {"matched", matched},
                {"recall", annotated ? double(matched) / annotated : 1.0},
                {"precision", proposed ? double(matched) / proposed : 1.0},
                {"kind_agreement", kinds_compared ? double(kinds_agreed) / kinds_compared : 1.0},
                {"strikes", rates(split[0])},
                {"blocks", rates(split[1])},
                {"semantics_confusion", semantics},
                {"kind_confusion", kinds}};
    }
};

const char* side_text(Side side) { return side == Side::left ? "left" : side == Side::right ? "right" : "none"; }

std::string folder_of(const std::string& source) {
    const std::size_t slash = source.find_last_of('/');
    return slash == std::string::npos ? "." : source.substr(0, slash);
}

void print_table(const char* title, const std::map<std::string, std::map<std::string, int>>& table) {
    std::set<std::string> columns;
    for (const auto& [row, cells] : table) {
        for (const auto& [column, count] : cells) columns.insert(column);
    }
    std::printf("  %s (annotated \\ proposed)\n  %-18s", title, "");
    for (const std::string& column : columns) std::printf(" %16s", column.c_str());
    std::printf("\n");
    for (const auto& [row, cells] : table) {
        std::printf("  %-18s", row.c_str());
        for (const std::string& column : columns) std::printf(" %16d", cells.count(column) ? cells.at(column) : 0);
        std::printf("\n");
    }
}

} // namespace

int run_detection_compare(const std::vector<std::string>& paths, const std::string& annotations_path, const CaptureOptions& options,
                          const StrikeThresholds& thresholds, bool as_json) {
    Result<RawAnnotations> annotations = annotations_read_file(annotations_path);
    if (!annotations) return input_error(annotations.error().message);
    std::map<std::string, FolderTally> folders;
    nlohmann::json files = nlohmann::json::array();
    for (const std::string& path : paths) {
        const std::string source = source_relative_to_root(resolve_capture_path(path, options.mocap_root), options.mocap_root);
        CaptureOptions file_options = options;
        if (const auto rate = annotations->capture_fps.find(source); rate != annotations->capture_fps.end() && !options.read.frame_rate_hz) {
            file_options.read.frame_rate_hz = rate->second;
        }
        Result<TimedCapture> capture = load_timed_capture(path, file_options, "suggest (strike speeds)");
        if (!capture) return input_error(capture.error().message);
        const BvhFile* file = &capture->file;
        const std::vector<StrikeSuggestion> proposed = strikes_detect(file->clip, capture->anatomy, std::nullopt, thresholds);

        std::vector<const RawAnnotatedClip*> annotated;
        for (const RawAnnotatedClip& clip : annotations->clips) {
            if (clip.source == source && clip.is_strike() && clip.segment && clip.hit_frame) annotated.push_back(&clip);
        }
        // Every (annotated, proposed) pair that may match, nearest hits first; then one to one.
        const int tolerance = std::max(1, int(std::lround(0.25 / file->clip.frame_time_s)));
        std::vector<std::tuple<int, int, int>> pairs; // distance, annotated, proposed
        for (int a = 0; a < int(annotated.size()); ++a) {
            for (int p = 0; p < int(proposed.size()); ++p) {
                const int distance = std::abs(*annotated[a]->hit_frame - proposed[p].hit_frame);
                const bool same = annotated[a]->semantics == strike_semantics_name(proposed[p].semantics) && annotated[a]->side == proposed[p].side;
                if (same && distance <= tolerance) pairs.emplace_back(distance, a, p);
            }
        }
        std::sort(pairs.begin(), pairs.end());
        std::vector<int> match_of_annotated(annotated.size(), -1), match_of_proposed(proposed.size(), -1);
        for (const auto& [distance, a, p] : pairs) {
            if (match_of_annotated[a] >= 0 || match_of_proposed[p] >= 0) continue;
            match_of_annotated[a] = p;
            match_of_proposed[p] = a;
        }

        FolderTally& tally = folders[folder_of(source)];
        ++tally.files;
        tally.annotated += int(annotated.size());
        tally.proposed += int(proposed.size());
        for (const RawAnnotatedClip* clip : annotated) ++tally.split[semantics_is_block(clip->semantics)][0];
        for (int p = 0; p < int(proposed.size()); ++p) {
            const bool block = proposed[p].semantics == StrikeSemantics::block;
            ++tally.split[block][1];
            tally.split[block][2] += match_of_proposed[p] >= 0;
        }
        nlohmann::json missed = nlohmann::json::array(), extra = nlohmann::json::array();
        for (int a = 0; a < int(annotated.size()); ++a) {
            const RawAnnotatedClip& clip = *annotated[a];
            const int p = match_of_annotated[a];
            if (p < 0) {
                ++tally.semantics[clip.semantics]["none"];
                missed.push_back({{"semantics", clip.semantics}, {"side", side_text(clip.side)}, {"hit_frame", *clip.hit_frame}});
                continue;
            }
            ++tally.matched;
            ++tally.semantics[clip.semantics][strike_semantics_name(proposed[p].semantics)];
            if (clip.kind != StrikeKind::none) {
                const std::string want = clip.semantics + " " + strike_kind_name(clip.kind);
                const std::string got = clip.semantics + " " + strike_kind_name(proposed[p].labels.kind);
                ++tally.kinds_compared;
                tally.kinds_agreed += want == got;
                ++tally.kinds[want][got];
            }
        }
        for (int p = 0; p < int(proposed.size()); ++p) {
            if (match_of_proposed[p] >= 0) continue;
            ++tally.semantics["none"][strike_semantics_name(proposed[p].semantics)];
            extra.push_back({{"semantics", strike_semantics_name(proposed[p].semantics)}, {"side", side_text(proposed[p].side)},
                             {"hit_frame", proposed[p].hit_frame}});
        }
        files.push_back({{"file", source}, {"annotated", annotated.size()}, {"proposed", proposed.size()}, {"missed", missed}, {"extra", extra}});
    }

    nlohmann::json by_folder = nlohmann::json::object();
    for (const auto& [folder, tally] : folders) by_folder[folder] = tally.to_json();
    if (as_json) {
        print_json({{"folders", by_folder}, {"files", files}});
        return k_exit_ok;
    }
    for (const auto& file : files) {
        if (file["missed"].empty() && file["extra"].empty()) continue;
        std::printf("%s: %d annotated, %d proposed;", file["file"].get<std::string>().c_str(), file["annotated"].get<int>(),
                    file["proposed"].get<int>());
        for (const auto& m : file["missed"]) {
            std::printf(" missed %s %s %d;", m["semantics"].get<std::string>().c_str(), m["side"].get<std::string>().c_str(), m["hit_frame"].get<int>());
        }
        for (const auto& e : file["extra"]) {
            std::printf(" extra %s %s %d;", e["semantics"].get<std::string>().c_str(), e["side"].get<std::string>().c_str(), e["hit_frame"].get<int>());
        }
        std::printf("\n");
    }
    for (const auto& [folder, tally] : folders) {
        std::printf("%s: %d files, %d annotated, %d proposed, %d matched: recall %.0f%%, precision %.0f%%, kind agreement %.0f%% (%d of %d)\n",
                    folder.c_str(), tally.files, tally.annotated, tally.proposed, tally.matched,
                    100.0 * (tally.annotated ? double(tally.matched) / tally.annotated : 1.0),
                    100.0 * (tally.proposed ? double(tally.matched) / tally.proposed : 1.0),
                    100.0 * (tally.kinds_compared ? double(tally.kinds_agreed) / tally.kinds_compared : 1.0), tally.kinds_agreed, tally.kinds_compared);
        const auto& s = tally.split;
        std::printf("  strikes: %d annotated, %d proposed, %d matched; blocks: %d annotated, %d proposed, %d matched\n", s[0][0], s[0][1], s[0][2],
                    s[1][0], s[1][1], s[1][2]);
        print_table("semantics", tally.semantics);
        print_table("kind", tally.kinds);
    }
    return k_exit_ok;
}

} // namespace kumite::cli
