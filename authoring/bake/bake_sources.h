#pragma once
// Inside the bake: the captures an annotation file cuts from, each read once, and the actors (distinct
// skeletons) they were performed by.

#include "bake.h"

#include "kumite/core/clip_mirror.h"
#include "kumite/core/rest_anatomy.h"
#include "kumite/formats/bvh_reader.h"

#include <optional>

namespace kumite::bake {

struct BakeSource {
    std::string name;                      // as annotated
    std::filesystem::path path;            // resolved
    BvhFile file;
    RestAnatomy anatomy;
    std::optional<MirrorSymmetry> symmetry; // when a clip asks for its mirror
    int actor = -1;
    std::vector<BakeWarning> notes;         // what the bake repaired in the capture, for the bake's warnings
};

struct BakeActor {
    std::string name;
    int first_source = 0; // whose skeleton and sizes it records
};

// Reads every source of the annotations (in order of first use) on `jobs` threads; `on_done` is called, one
// call at a time, as sources finish.
Result<std::vector<BakeSource>> bake_read_sources(const RawAnnotations& annotations, std::string_view annotations_name,
                                                  const BakeOptions& options, int jobs, const std::function<void(int done, int total)>& on_done);

// Groups sources by skeleton (same joints, parents and offsets) and names the groups after their folders.
std::vector<BakeActor> bake_find_actors(std::vector<BakeSource>& sources);

DbActor bake_actor_record(const BakeSource& source);

} // namespace kumite::bake
