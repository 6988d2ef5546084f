#pragma once
// glTF reading below the character (formats/src only): tinygltf loading without images, and accessors read with
// every offset, stride, count and index checked against the buffers, so a hostile file is refused, never read
// out of bounds.

#include "kumite/core/result.h"
#include "kumite/formats/gltf_reader.h"

#include <tiny_gltf.h>

#include <Eigen/Core>

#include <cstdint>
#include <filesystem>
#include <span>
#include <string>
#include <vector>

namespace kumite::gltf {

inline Error fail(const std::string& what) { return make_error(ErrorCode::invalid, what); }

// A .glb (by its magic) or a .gltf's JSON; external buffers relative to base_dir; images are not decoded.
Result<tinygltf::Model> load_model(std::span<const std::uint8_t> bytes, const std::filesystem::path& base_dir);

// Reads accessor `index` element by element after checking it lies inside its buffer view and buffer.
class AccessorReader {
public:
    // `what` names the use in messages ("POSITION of mesh 0 primitive 1").
    static Result<AccessorReader> open(const tinygltf::Model& model, int index, const std::string& what);
    std::size_t count() const { return m_count; }
    int components() const { return m_components; }
    int component_type() const { return m_component_type; }
    // Component c of element i as a double (normalised integers mapped to 0..1 when the accessor says so).
    double value(std::size_t element, int component) const;
    std::uint32_t index_value(std::size_t element) const; // unsigned integer components

private:
    const std::uint8_t* m_data = nullptr;
    std::size_t m_count = 0, m_stride = 0;
    int m_components = 0, m_component_type = 0, m_component_size = 0;
    bool m_normalised = false;
};

// The skin's inverse bind matrices (identity when the skin has none), checked finite.
Result<std::vector<Eigen::Matrix4d>> inverse_bind_matrices(const tinygltf::Model& model, int skin_index);

// Appends every triangle primitive of every mesh node using skin `skin_index` to `mesh`, in bind space (joints mapped
// through `skeleton_of_skin`, weights renormalised, the material's base colour kept from the first primitive).
Result<void> read_skinned_primitives(const tinygltf::Model& model, int skin_index, const std::vector<int>& skeleton_of_skin, SkinnedMesh& mesh);

} // namespace kumite::gltf
