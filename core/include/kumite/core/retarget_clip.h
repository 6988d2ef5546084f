#pragma once
// Retargeting a whole clip through the morphology-independent representation: encode every frame on the
// source skeleton, detect the source's foot contacts, decode onto the target skeleton with planted feet pinned
// where the source planted them (released over 0.1 s), and measure the result.

#include "kumite/core/foot_contacts.h"
#include "kumite/core/mir.h"

namespace kumite {

struct RetargetReport {
    int frames = 0;
    int contacts = 0;                    // planted intervals found on the source, both feet
    double bone_length_error_m = 0.0;    // max over frames and bones of | |child - parent| - rest length |
    double foot_drift_m = 0.0;           // max horizontal distance of a planted ankle from where its contact began
    double floor_penetration_m = 0.0;    // max depth of a foot point (joints and End Sites) below y = 0
    double limb_extension_error = 0.0;   // max | source - output | of |extremity - limb root| / limb length
    double encode_decode_us_median = 0.0; // per frame, encode + decode
    double encode_decode_us_p99 = 0.0;
    double foot_lock_us_median = 0.0;     // per frame, placing pinned feet (a second decode on planted frames)
    double foot_lock_us_p99 = 0.0;
};

// `target` supplies the skeleton (its frames are not used). Both anatomies come from rest_anatomy_build.
Clip retarget_clip(RetargetReport& report, const Clip& source, const RestAnatomy& source_anatomy, const Skeleton& target,
                   const RestAnatomy& target_anatomy);

} // namespace kumite
