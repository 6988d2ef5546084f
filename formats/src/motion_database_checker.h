#pragma once
// What the motion database's opener and verifier share: a view's sections looked up by tag, and refusals that
// name the source, the section, the record and its byte.

#include "kumite/formats/motion_database_file.h"

#include <cmath>
#include <span>
#include <string>

namespace kumite::database_checks {

class Checker {
public:
    Checker(std::string_view source, const DatabaseImage& image) : m_source(source), m_image(image) {}

    // The section's records, or an error when it is missing or holds records of another size.
    template <class T>
    Result<std::span<const T>> records(std::uint32_t tag) const {
        const DatabaseSection* section = m_image.find(tag);
        if (!section) return fail(0, "no " + section_tag_name(tag) + " section (not a motion database, or a damaged one)");
        if (section->element_size != sizeof(T)) {
            return fail(section->offset, section_tag_name(tag) + " records are " + std::to_string(section->element_size) +
                                             " bytes, this kumite reads " + std::to_string(sizeof(T)));
        }
        return std::span<const T>(reinterpret_cast<const T*>(section->bytes.data()), section->count);
    }

    Error fail(std::uint64_t byte, const std::string& what) const {
        return make_error(ErrorCode::invalid, std::string(m_source) + ": byte " + std::to_string(byte) + ": " + what);
    }
    // A refusal at record `index` of section `tag` (which records() found).
    template <class T>
    Error fail_at(std::uint32_t tag, std::size_t index, const std::string& what) const {
        const DatabaseSection* section = m_image.find(tag);
        return fail(section->offset + index * sizeof(T), section_tag_name(tag) + " " + std::to_string(index) + ": " + what);
    }

private:
    std::string_view m_source;
    const DatabaseImage& m_image;
};

inline bool all_finite(std::span<const float> values) {
    bool finite = true;
    for (float v : values) finite &= std::isfinite(v); // no early exit: the loop vectorises
    return finite;
}
template <std::size_t N>
bool all_finite(const float (&values)[N]) {
    return all_finite(std::span<const float>(values, N));
}

inline std::string out_of_range(std::uint64_t value, std::uint64_t count, const char* what) {
    return std::to_string(value) + " is out of range (" + std::to_string(count) + " " + what + ")";
}

// The structure: what open() checks (motion_database_structure.cpp). The view's spans are the sections'.
Result<void> check_structure(const MotionDatabaseView& db, const Checker& check);
// The per-pose values: what verify_values() checks (motion_database_values.cpp), on a view whose structure passed.
Result<void> check_values(const MotionDatabaseView& db, const Checker& check);

} // namespace kumite::database_checks
