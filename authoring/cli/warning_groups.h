#pragma once
// Warnings of a command that reads many files (bake, suggest), grouped by kind so that a folder of captures with the
// same quirk gives one line, not one per file. A kind is a warning's message with its numbers and quoted names
// masked ("slid 14 cm" and "slid 19 cm" are one kind), so no list of kinds is kept anywhere. Printed as one line
// per kind, the first warning of the kind in full with how many there are, or every warning with --verbose.

#include <iosfwd>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace kumite::cli {

class WarningGroups {
public:
    // A warning about `where` (a file, "file:line", "annotations.json: clip NAME") saying `what`.
    void add(std::string where, std::string what);
    // A reader's warning "SOURCE: what" or "SOURCE:LINE: what" about the file it read as `source`.
    void add_from_reader(std::string_view source, std::string_view message);

    int count() const;
    int kind_count() const { return static_cast<int>(m_kinds.size()); }

    // verbose: "warning: WHERE: WHAT", one line per warning, in the order added. Otherwise one line per kind, in
    // the order kinds first appeared: its first warning as above, followed by
    // " [N like this in all; --verbose lists them]" when there are more.
    void print(std::ostream& out, bool verbose) const;

private:
    struct Warning {
        std::string where;
        std::string what;
    };
    struct Kind {
        std::string key;
        std::vector<Warning> warnings;
    };
    std::vector<Kind> m_kinds;
    std::vector<std::pair<int, int>> m_order; // (kind, index in kind) of every warning, in the order added
};

// The kind of a warning's message: digits runs (with their decimal point and sign) become '#', text in single
// or double quotes becomes '...'.
std::string warning_kind(std::string_view what);

} // namespace kumite::cli
