// libFuzzer target: any bytes handed to the glTF character reader are either refused with a message or give a
// character whose skeleton is valid and whose mesh indexes only its own vertices and joints (ASan checks reads).

#include "kumite/formats/gltf_reader.h"

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    if (size > (std::size_t(4) << 20)) return 0;
    // No base folder: a .gltf naming external buffers finds none, so the fuzzer never reads files.
    kumite::Result<kumite::GltfCharacter> read = kumite::gltf_parse(std::span<const std::uint8_t>(data, size), "fuzz.glb", "/nonexistent-fuzz-dir");
    if (!read) {
        if (read.error().message.empty()) std::abort();
        return 0;
    }
    const kumite::Skeleton& skeleton = read->character.clip.skeleton;
    skeleton.assert_valid();
    const kumite::SkinnedMesh& mesh = read->mesh;
    if (mesh.bind_to_rest.size() != std::size_t(skeleton.joint_count())) std::abort();
    if (mesh.normals.size() != mesh.vertex_count() || mesh.joints.size() != mesh.vertex_count() || mesh.weights.size() != mesh.vertex_count()) std::abort();
    for (std::uint32_t index : mesh.triangles) {
        if (index >= mesh.vertex_count()) std::abort();
    }
    for (std::size_t v = 0; v < mesh.vertex_count(); ++v) {
        float total = 0.0f;
        for (int k = 0; k < 4; ++k) {
            if (mesh.joints[v][k] >= skeleton.joint_count()) std::abort();
            total += mesh.weights[v][k];
        }
        if (!(std::abs(total - 1.0f) < 1e-3f)) std::abort();
    }
    if (!std::isfinite(read->character.height_m)) std::abort();
    return 0;
}
