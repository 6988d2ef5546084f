// kumite convert: read a capture and write it back, keeping hierarchy, names, channel layout, rotation
// orders and the file's length unit.

#include "capture_loading.h"
#include "commands.h"
#include "kumite/formats/bvh_writer.h"

#include <iostream>

namespace kumite::cli {

const CommandSpec& convert_spec() {
    static const CommandSpec spec{
        "convert",
        "IN.bvh OUT.bvh [--unit ...] [--out-unit m|cm|mm|in|cmu]",
        "Reads a BVH capture and writes it back: same joint names, hierarchy, channel layout and rotation\n"
        "orders, same world positions when read again. The output keeps the input's unit unless --out-unit\n"
        "says otherwise. The output is written to a temporary file and renamed, never left half-written.",
        2, 2,
        {unit_flag(), strict_flag(), fps_flag(), {"out-unit", "m|cm|mm|in|cmu", "length unit of the written file (default: the input's)"},
         mocap_root_flag()}};
    return spec;
}

int run_convert(int argc, char** argv) {
    Arguments arguments;
    if (std::optional<int> status = parse_command_line(convert_spec(), argc, argv, arguments)) return *status;
    Result<CaptureOptions> options = capture_options_from(arguments);
    if (!options) return usage_error(convert_spec(), options.error().message);
    std::optional<LengthUnit> out_unit;
    if (const std::optional<std::string> name = arguments.value("out-unit")) {
        Result<LengthUnit> unit = length_unit_from_name(*name);
        if (!unit) return usage_error(convert_spec(), unit.error().message);
        out_unit = *unit;
    }
    Result<BvhFile> file = load_capture(arguments.positionals[0], *options);
    if (!file) return input_error(file.error().message);

    const std::filesystem::path output = arguments.positionals[1];
    const LengthUnit unit = out_unit ? *out_unit : file->unit;
    if (Result<void> written = bvh_write_file(output, file->clip, file->layout, unit); !written) {
        return input_error(written.error().message);
    }
    std::cout << "wrote " << output.string() << ": " << file->clip.skeleton.joint_count() << " joints, "
              << file->clip.frame_count() << " frames, unit " << unit.name << "\n";
    return k_exit_ok;
}

} // namespace kumite::cli
