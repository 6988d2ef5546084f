#include "kumite/formats/length_unit.h"

namespace kumite {

Result<LengthUnit> length_unit_from_name(std::string_view name) {
    if (name == "m") return LengthUnit{"m", 1.0};
    if (name == "cm") return LengthUnit{"cm", 0.01};
    if (name == "mm") return LengthUnit{"mm", 0.001};
    if (name == "in") return LengthUnit{"in", 0.0254};
    if (name == "cmu") return LengthUnit{"cmu", k_cmu_unit_m};
    return make_error(ErrorCode::invalid,
                      "unknown length unit '" + std::string(name) + "' (expected auto, m, cm, mm, in or cmu)");
}

LengthUnit length_unit_for_height(double height) {
    // Boundaries sit between the ranges a 1.0-2.6 m human occupies in each unit:
    // m 1-2.6, CMU 18-46, in 39-102, cm 100-260, mm 1000-2600. CMU and inches overlap for giants and
    // children; 44 splits them at 2.5 m (CMU) / 1.12 m (in).
    if (height < 4.0) return {"m", 1.0};
    if (height < 44.0) return {"cmu", k_cmu_unit_m};
    if (height < 100.0) return {"in", 0.0254};
    if (height < 400.0) return {"cm", 0.01};
    return {"mm", 0.001};
}

} // namespace kumite
