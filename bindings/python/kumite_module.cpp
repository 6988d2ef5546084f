// The Python module `kumite` (pybind11): captures as numpy arrays, the body map, bake, a database's query and adapt,
// and bouts stepped from Python. Errors raise kumite.Error (a RuntimeError) with kumite's message (file:line for a
// bad file). Arrays are float64, metres, Y up.

#include "store_binding.h"
#include "strike_reports.h"
#include "strike_stage.h"

#include "bake.h"
#include "kumite/core/forward_kinematics.h"
#include "kumite/formats/annotation_file.h"
#include "kumite/formats/capture_file.h"
#include "kumite/formats/character_catalog.h"
#include "kumite/formats/length_unit.h"
#include "kumite/formats/motion_database_file.h"
#include "kumite/runtime/bout.h"
#include "kumite/runtime/bout_cast.h"
#include "kumite/runtime/bout_event_json.h"
#include "kumite/runtime/strike_playback.h"

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <chrono>
#include <stdexcept>

namespace py = pybind11;

namespace kumite::python {

struct KumiteError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

template <class T>
T take(Result<T> result) {
    if (!result) throw KumiteError(result.error().message);
    return std::move(*result);
}

void take(Result<void> result) {
    if (!result) throw KumiteError(result.error().message);
}

py::object json_to_python(const nlohmann::json& value) { return py::module_::import("json").attr("loads")(value.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace)); }

Eigen::Vector3d point_from(const std::vector<double>& xyz, const char* what) {
    if (xyz.size() != 3) throw py::value_error(std::string(what) + " must be 3 numbers (x, y, z in metres)");
    const Eigen::Vector3d point(xyz[0], xyz[1], xyz[2]);
    if (!point.allFinite()) throw py::value_error(std::string(what) + " must be finite");
    return point;
}

// ---- captures

struct Capture {
    BvhFile file;
    std::string path;
};

Capture capture_open(const std::string& path, std::optional<std::string> unit, std::optional<double> fps, bool strict) {
    BvhReadOptions options;
    if (unit && *unit != "auto") options.unit = take(length_unit_from_name(*unit));
    if (fps) {
        if (!(*fps > 0.0) || *fps > 100000.0) throw py::value_error("fps must be more than 0 and at most 100000");
        options.frame_rate_hz = *fps;
    }
    options.strict = strict;
    return {take(capture_read_file(path, options)), path};
}

py::array_t<double> capture_positions(const Capture& capture, std::optional<std::vector<int>> frames) {
    const Clip& clip = capture.file.clip;
    std::vector<int> chosen;
    if (frames) {
        for (int frame : *frames) {
            if (frame < 0 || frame >= clip.frame_count()) {
                throw py::index_error("frame " + std::to_string(frame) + " is out of range: " + capture.path + " has " + std::to_string(clip.frame_count()) + " frames");
            }
        }
        chosen = *frames;
    } else {
        chosen.resize(std::size_t(clip.frame_count()));
        for (int f = 0; f < clip.frame_count(); ++f) chosen[std::size_t(f)] = f;
    }
    const int joints = clip.skeleton.joint_count();
    py::array_t<double> out({py::ssize_t(chosen.size()), py::ssize_t(joints), py::ssize_t(3)});
    auto view = out.mutable_unchecked<3>();
    std::vector<Eigen::Vector3d> positions(static_cast<std::size_t>(joints));
    std::vector<Eigen::Quaterniond> rotations(static_cast<std::size_t>(joints));
    for (std::size_t i = 0; i < chosen.size(); ++i) {
        forward_kinematics(positions, rotations, clip.skeleton, clip.pose(chosen[i]));
        for (int j = 0; j < joints; ++j) {
            for (int k = 0; k < 3; ++k) view(py::ssize_t(i), j, k) = positions[std::size_t(j)][k];
        }
    }
    return out;
}

py::dict capture_body_map(const Capture& capture) {
    py::dict parts;
    for (int p = 0; p < k_body_part_count; ++p) {
        const int joint = capture.file.body_map.joint(static_cast<BodyPart>(p));
        if (joint >= 0) parts[py::str(std::string(body_part_name(static_cast<BodyPart>(p))))] = capture.file.clip.skeleton.names[std::size_t(joint)];
    }
    return parts;
}

// ---- databases, query and adapt

struct Database {
    MotionDatabase database;
    std::string path;
};

StrikeRequest request_from(const std::string& command, std::optional<std::string> side, std::optional<std::string> kind, std::optional<std::string> height) {
    StrikeRequest request;
    request.semantics = command;
    if (side && *side != "any") {
        if (*side != "left" && *side != "right") throw py::value_error("side must be 'left', 'right' or 'any', not '" + *side + "'");
        request.side = *side == "left" ? Side::left : Side::right;
    }
    if (kind && *kind != "any") {
        const std::optional<StrikeKind> parsed = strike_kind_from_name(*kind);
        if (!parsed || *parsed == StrikeKind::none || !strike_kind_fits(command, *parsed)) throw py::value_error("'" + *kind + "' is not a kind of " + command);
        request.kind = *parsed;
    }
    if (height && *height != "any") {
        const std::optional<StrikeHeight> parsed = strike_height_from_name(*height);
        if (!parsed || *parsed == StrikeHeight::none) throw py::value_error("height must be 'low', 'middle', 'high' or 'any', not '" + *height + "'");
        request.height = *parsed;
    }
    return request;
}

std::unique_ptr<StrikeStage> stage_for(const Database& db, const std::string& character, const std::optional<std::string>& characters_dir,
                                       const StrikeRequest& request) {
    BvhFile file = take(load_character(characters_dir ? std::filesystem::path(*characters_dir) : default_characters_dir(), character));
    return take(strike_stage_create(db.database.view(), std::move(file), character, request, db.path));
}

RetrievalResult retrieve(StrikeStage& stage, const Eigen::Vector3d& target, const std::string& order, double* latency_us = nullptr) {
    RetrievalQuery query = stage.query;
    query.target_world = target;
    RetrievalWorkspace workspace = stage.retriever->make_workspace();
    const auto started = std::chrono::steady_clock::now();
    const RetrievalResult result = stage.retriever->query(query, workspace);
    if (latency_us) *latency_us = std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - started).count();
    if (!result.found) throw KumiteError("no " + order + " can start from the guard");
    return result;
}

py::object database_query(const Database& db, const std::string& character, const std::vector<double>& target, const std::string& command,
                          std::optional<std::string> side, std::optional<std::string> kind, std::optional<std::string> height,
                          std::optional<std::string> characters_dir) {
    const StrikeRequest request = request_from(command, side, kind, height);
    std::unique_ptr<StrikeStage> stage = stage_for(db, character, characters_dir, request);
    double latency_us = 0.0;
    const RetrievalResult result = retrieve(*stage, point_from(target, "target"), strike_order_description(command, request.side, request.kind, request.height), &latency_us);
    return json_to_python(query_result_json(*stage->retriever, result, latency_us));
}

py::tuple database_adapt(const Database& db, const std::string& character, const std::vector<double>& target_xyz, const std::string& command,
                         std::optional<std::string> side, std::optional<std::string> kind, std::optional<std::string> height, int lead,
                         std::optional<std::string> characters_dir) {
    if (lead < 0 || lead > 1000) throw py::value_error("lead must be 0 to 1000 frames");
    const StrikeRequest request = request_from(command, side, kind, height);
    std::unique_ptr<StrikeStage> stage = stage_for(db, character, characters_dir, request);
    const Eigen::Vector3d target = point_from(target_xyz, "target");
    const RetrievalResult retrieved = retrieve(*stage, target, strike_order_description(command, request.side, request.kind, request.height));
    const MotionDatabaseView& view = db.database.view();
    const StrikePlan plan{retrieved.clip, retrieved.start_frame, retrieved.contact_frame, retrieved.clip_to_world, target};
    const StrikePlayback playback = strike_playback_run(*stage->rig, view, stage->standing, plan, lead);
    const Clip& motion = playback.motion;
    const int joints = motion.skeleton.joint_count();
    py::array_t<double> positions({py::ssize_t(motion.frame_count()), py::ssize_t(joints), py::ssize_t(3)});
    auto out = positions.mutable_unchecked<3>();
    std::vector<Eigen::Vector3d> model(static_cast<std::size_t>(joints));
    std::vector<Eigen::Quaterniond> rotations(static_cast<std::size_t>(joints));
    for (int f = 0; f < motion.frame_count(); ++f) {
        forward_kinematics(model, rotations, motion.skeleton, motion.pose(f));
        for (int j = 0; j < joints; ++j) {
            for (int k = 0; k < 3; ++k) out(f, j, k) = model[std::size_t(j)][k];
        }
    }
    return py::make_tuple(positions, json_to_python(adapt_report_json(playback, retrieved, view, stage->character.clip.skeleton, target)));
}

py::dict bake_annotations(const std::string& annotations_path, const std::string& output, std::optional<std::string> mocap_root, std::optional<double> fps, int jobs) {
    RawAnnotations annotations = take(annotations_read_file(annotations_path));
    bake::BakeOptions options;
    options.mocap_root = mocap_root ? std::filesystem::path(*mocap_root) : locate_data_folder("KUMITE_MOCAP_ROOT", "data/mocap");
    options.capture_fps = fps;
    options.jobs = jobs;
    bake::BakeResult baked;
    {
        py::gil_scoped_release unlocked; // a bake takes seconds: let other Python threads run
        Result<bake::BakeResult> result = bake::bake_database(annotations, annotations_path, options);
        if (result) {
            Result<void> written = motion_database_write(output, result->database.view());
            if (!written) result = written.error();
        }
        if (!result) {
            py::gil_scoped_acquire locked;
            throw KumiteError(result.error().message);
        }
        baked = std::move(*result);
    }
    const MotionDatabaseView view = baked.database.view();
    py::dict summary;
    summary["output"] = output;
    summary["clips"] = view.clips.size();
    summary["poses"] = view.poses.size();
    summary["clusters"] = view.clusters.size();
    summary["actors"] = view.actors.size();
    summary["seconds"] = baked.seconds;
    std::vector<std::string> warnings;
    for (const bake::BakeWarning& warning : baked.warnings) warnings.push_back(warning.text());
    summary["warnings"] = warnings;
    return summary;
}

// ---- bouts

struct PyBout {
    std::unique_ptr<Bout> bout;
    bool fed = false;
};

PyBout bout_create(const Database& db, std::optional<std::string> character, std::optional<std::string> characters_dir, std::optional<std::string> tracker,
                   int fighters, const std::string& aim, bool defence, std::uint64_t seed, double rate_hz) {
    if (fighters < 1 || fighters > 10000) throw py::value_error("fighters must be 1 to 10000");
    if (aim != "latched" && aim != "predicted") throw py::value_error("aim must be 'latched' or 'predicted'");
    if (!(rate_hz >= 1.0 && rate_hz <= 10000.0)) throw py::value_error("rate_hz must be 1 to 10000");
    BoutCast cast = take(load_bout_cast(characters_dir ? std::filesystem::path(*characters_dir) : default_characters_dir(), character.value_or("")));
    std::unique_ptr<HeadTracker> source = tracker ? take(HeadTracker::open(*tracker, DtrackConfig{}, seed)) : HeadTracker::fed();
    BoutOptions options;
    options.fighters = fighters;
    options.start_character = cast.start;
    options.rate_hz = rate_hz;
    options.fighter.aim = aim == "predicted" ? FighterAim::predicted : FighterAim::latched;
    options.fighter.defence.enabled = defence;
    return {take(Bout::create(db.database.view(), std::move(cast.characters), std::move(source), options)), !tracker.has_value()};
}

const Fighter& fighter_at(const PyBout& bout, int fighter) {
    if (fighter < 0 || fighter >= bout.bout->fighter_count()) throw py::index_error("no fighter " + std::to_string(fighter));
    return bout.bout->fighter(fighter);
}

void bout_set_user(PyBout& bout, std::optional<std::vector<double>> head, std::optional<std::vector<double>> left_hand,
                   std::optional<std::vector<double>> right_hand) {
    if (!bout.fed) throw KumiteError("this bout's user comes from its tracker (tracker= was given)");
    UserHands hands;
    const std::optional<std::vector<double>>* given[2] = {&left_hand, &right_hand};
    for (int side = 0; side < 2; ++side) {
        if (!*given[side]) continue;
        hands.present[std::size_t(side)] = true;
        hands.world[std::size_t(side)] = point_from(**given[side], side ? "right_hand" : "left_hand");
    }
    if (!head) return bout.bout->tracker().feed(nullptr, hands);
    const Eigen::Vector3d point = point_from(*head, "head");
    bout.bout->tracker().feed(&point, hands);
}

py::array_t<double> bout_positions(const PyBout& bout, int fighter) {
    const std::span<const Eigen::Vector3d> positions = fighter_at(bout, fighter).positions();
    py::array_t<double> out({py::ssize_t(positions.size()), py::ssize_t(3)});
    auto view = out.mutable_unchecked<2>();
    for (std::size_t j = 0; j < positions.size(); ++j) {
        for (int k = 0; k < 3; ++k) view(py::ssize_t(j), k) = positions[j][k];
    }
    return out;
}

py::array_t<double> bout_world_transforms(const PyBout& bout, int fighter) {
    const Fighter& f = fighter_at(bout, fighter);
    const std::span<const Eigen::Vector3d> positions = f.positions();
    py::array_t<double> out({py::ssize_t(positions.size()), py::ssize_t(4), py::ssize_t(4)});
    auto view = out.mutable_unchecked<3>();
    for (std::size_t j = 0; j < positions.size(); ++j) {
        Eigen::Matrix4d matrix = Eigen::Matrix4d::Identity();
        matrix.topLeftCorner<3, 3>() = f.rotations()[j].toRotationMatrix();
        matrix.topRightCorner<3, 1>() = positions[j];
        for (int r = 0; r < 4; ++r) {
            for (int c = 0; c < 4; ++c) view(py::ssize_t(j), r, c) = matrix(r, c);
        }
    }
    return out;
}

// The same stepping as a Python loop of set_user + step, in C++: the baseline of the binding's cost.
double bout_step_loop_us(PyBout& bout, double start_s, int frames, const std::vector<double>& head_xyz) {
    const Eigen::Vector3d head = point_from(head_xyz, "head");
    const auto started = std::chrono::steady_clock::now();
    for (int frame = 0; frame < frames; ++frame) {
        if (bout.fed) bout.bout->tracker().feed(&head, UserHands{});
        bout.bout->step(start_s + frame / bout.bout->rate_hz());
    }
    return std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - started).count();
}

} // namespace kumite::python

PYBIND11_MODULE(kumite, m) {
    using namespace kumite;
    using namespace kumite::python;
    m.doc() = "kumite: the virtual kung-fu sparring partner's toolkit (captures, bake, retrieval and adaptation, bouts)";
    py::register_exception<KumiteError>(m, "Error", PyExc_RuntimeError);
    m.attr("__version__") = "0.1.0";

    py::class_<Capture>(m, "Capture", "A motion capture (BVH) in metres, read as kumite reads it.")
        .def(py::init(&capture_open), py::arg("path"), py::arg("unit") = py::none(), py::arg("fps") = py::none(), py::arg("strict") = false,
             "Reads a BVH file. unit: None/'auto' (detected from the standing height), 'm', 'cm', 'mm', 'in', 'cmu'. fps: the rate when the "
             "file gives none (Frame Time: 0). Raises kumite.Error with file:line for a malformed file.")
        .def_property_readonly("path", [](const Capture& c) { return c.path; })
        .def_property_readonly("joint_names", [](const Capture& c) { return c.file.clip.skeleton.names; })
        .def_property_readonly("parents", [](const Capture& c) { return c.file.clip.skeleton.parents; })
        .def_property_readonly("frame_count", [](const Capture& c) { return c.file.clip.frame_count(); })
        .def_property_readonly("fps", [](const Capture& c) -> std::optional<double> {
            return c.file.clip.has_frame_rate() ? std::optional<double>(1.0 / c.file.clip.frame_time_s) : std::nullopt;
        })
        .def_property_readonly("unit", [](const Capture& c) { return c.file.unit.name; })
        .def_property_readonly("height_m", [](const Capture& c) { return c.file.height_m; })
        .def_property_readonly("warnings", [](const Capture& c) { return c.file.warnings; })
        .def("positions", &capture_positions, py::arg("frames") = py::none(),
             "World positions of every joint (End Sites excluded): a float64 array (frames, joints, 3) in metres, Y up; frames: a list of "
             "indices (default every frame).")
        .def("body_map", &capture_body_map, "The body parts found, part name ('hand_l', 'head', ...) -> joint name.")
        .def("__repr__", [](const Capture& c) {
            return "<kumite.Capture '" + c.path + "': " + std::to_string(c.file.clip.skeleton.joint_count()) + " joints, " +
                   std::to_string(c.file.clip.frame_count()) + " frames>";
        });

    py::class_<Database>(m, "Database", "A motion database (.kdb), memory-mapped and validated.")
        .def(py::init([](const std::string& path) { return Database{take(MotionDatabase::open(path)), path}; }), py::arg("path"))
        .def_property_readonly("path", [](const Database& db) { return db.path; })
        .def_property_readonly("strike_count", [](const Database& db) {
            int strikes = 0;
            for (const DbClip& clip : db.database.view().clips) strikes += db_clip_is_strike(clip);
            return strikes;
        })
        .def("query", &database_query, py::arg("character"), py::arg("target"), py::arg("command"), py::arg("side") = py::none(),
             py::arg("kind") = py::none(), py::arg("height") = py::none(), py::arg("characters_dir") = py::none(),
             "The strike retrieval picks for the character standing at the origin in its guard and a target (x, y, z): a dict as "
             "`kumite query --json` prints.")
        .def("adapt", &database_adapt, py::arg("character"), py::arg("target"), py::arg("command"), py::arg("side") = py::none(),
             py::arg("kind") = py::none(), py::arg("height") = py::none(), py::arg("lead") = 6, py::arg("characters_dir") = py::none(),
             "The retrieved strike adapted to the character and the target, from the guard to the recovery: (positions, report), "
             "positions a float64 array (frames, joints, 3) in metres, report a dict with the keys of `kumite adapt --report`.");

    m.def("bake", &bake_annotations, py::arg("annotations"), py::arg("output"), py::arg("mocap_root") = py::none(), py::arg("fps") = py::none(), py::arg("jobs") = 0,
          "Bakes an annotation file into a motion database at output (written to a temporary, then renamed); returns a summary dict.");

    py::class_<PyBout>(m, "Bout", "A bout: fighters against one user, stepped by the caller.")
        .def(py::init(&bout_create), py::arg("database"), py::arg("character") = py::none(), py::arg("characters_dir") = py::none(),
             py::arg("tracker") = py::none(), py::arg("fighters") = 1, py::arg("aim") = "latched", py::arg("defence") = true, py::arg("seed") = 1,
             py::arg("rate_hz") = 60.0, py::keep_alive<1, 2>(),
             "tracker None: the caller feeds the user with set_user() before each step; else a source as `kumite play --tracker` takes it.")
        .def("set_user", &bout_set_user, py::arg("head"), py::arg("left_hand") = py::none(), py::arg("right_hand") = py::none(),
             "The user for the next steps: head (x, y, z) or None (not tracked), hands (x, y, z) or None.")
        .def("command", [](PyBout& bout, const std::string& line) { take(bout.bout->command(line)); }, py::arg("line"),
             "A supervisor command line ('punch left', 'kick', 'character giant', 'aim predicted', ...), applied at the next step.")
        .def("step", [](PyBout& bout, double t_s) {
            if (!std::isfinite(t_s)) throw py::value_error("t_s must be finite");
            bout.bout->step(t_s);
        }, py::arg("t_s"))
        .def("events", [](const PyBout& bout) {
            py::list events;
            for (const BoutEvent& event : bout.bout->events()) events.append(py::module_::import("json").attr("loads")(bout_event_json(*bout.bout, event)));
            return events;
        }, "The last step's events as dicts (the lines of `kumite play --events`).")
        .def_property_readonly("fighter_count", [](const PyBout& bout) { return bout.bout->fighter_count(); })
        .def_property_readonly("now_s", [](const PyBout& bout) { return bout.bout->now_s(); })
        .def("joint_names", [](const PyBout& bout, int fighter) { return bout.bout->character_skeleton(fighter_at(bout, fighter).character()).names; },
             py::arg("fighter") = 0)
        .def("parents", [](const PyBout& bout, int fighter) { return bout.bout->character_skeleton(fighter_at(bout, fighter).character()).parents; },
             py::arg("fighter") = 0)
        .def("positions", &bout_positions, py::arg("fighter") = 0, "The fighter's joints in the world as of the last step: (joints, 3), metres.")
        .def("world_transforms", &bout_world_transforms, py::arg("fighter") = 0, "The fighter's joints' world matrices: (joints, 4, 4).")
        .def("_step_loop_us", &bout_step_loop_us, py::arg("start_s"), py::arg("frames"), py::arg("head"),
             "Benchmark baseline: steps `frames` frames in C++ feeding a still head; returns the microseconds taken.");

    // The training store, read: kumite.Store (store_binding.cpp).
    bind_store(m);
}
