#include "warning_groups.h"

#include <cctype>
#include <ostream>

namespace kumite::cli {

std::string warning_kind(std::string_view what) {
    std::string kind;
    for (std::size_t i = 0; i < what.size();) {
        const char c = what[i];
        if (c == '\'' || c == '"') { // a quoted name or value: one kind whatever it quotes
            const std::size_t close = what.find(c, i + 1);
            if (close != std::string_view::npos) {
                kind += c;
                kind += "...";
                kind += c;
                i = close + 1;
                continue;
            }
        }
        const bool sign = (c == '-' || c == '+') && i + 1 < what.size() && std::isdigit(static_cast<unsigned char>(what[i + 1])) &&
                          (i == 0 || !std::isalnum(static_cast<unsigned char>(what[i - 1])));
        if (std::isdigit(static_cast<unsigned char>(c)) || sign) {
            std::size_t end = i + 1;
            while (end < what.size() && (std::isdigit(static_cast<unsigned char>(what[end])) ||
                                         (what[end] == '.' && end + 1 < what.size() && std::isdigit(static_cast<unsigned char>(what[end + 1]))))) {
                ++end;
            }
            kind += '#';
            i = end;
            continue;
        }
        kind += c;
        ++i;
    }
    return kind;
}

void WarningGroups::add(std::string where, std::string what) {
    std::string key = warning_kind(what);
    int kind = 0;
    while (kind < kind_count() && m_kinds[kind].key != key) ++kind;
    if (kind == kind_count()) m_kinds.push_back({std::move(key), {}});
    m_kinds[kind].warnings.push_back({std::move(where), std::move(what)});
    m_order.emplace_back(kind, static_cast<int>(m_kinds[kind].warnings.size()) - 1);
}

void WarningGroups::add_from_reader(std::string_view source, std::string_view message) {
    std::size_t at = 0;
    if (!source.empty() && message.starts_with(source)) {
        at = source.size();
        if (at < message.size() && message[at] == ':') { // "SOURCE:LINE: " keeps its line in `where`
            std::size_t digits = at + 1;
            while (digits < message.size() && std::isdigit(static_cast<unsigned char>(message[digits]))) ++digits;
            if (digits > at + 1 && message.substr(digits).starts_with(": ")) at = digits;
        }
        if (message.substr(at).starts_with(": ")) add(std::string(message.substr(0, at)), std::string(message.substr(at + 2)));
        else add({}, std::string(message)); // names its source some other way: kept whole
        return;
    }
    add(std::string(source), std::string(message)); // does not name its source: the source is its where
}

int WarningGroups::count() const { return static_cast<int>(m_order.size()); }

void WarningGroups::print(std::ostream& out, bool verbose) const {
    auto line = [&](const Warning& warning) -> std::ostream& {
        out << "warning: ";
        if (!warning.where.empty()) out << warning.where << ": ";
        return out << warning.what;
    };
    if (verbose) {
        for (const auto& [kind, index] : m_order) line(m_kinds[kind].warnings[index]) << "\n";
        return;
    }
    for (const Kind& kind : m_kinds) {
        line(kind.warnings.front());
        if (kind.warnings.size() > 1) out << " [" << kind.warnings.size() << " like this in all; --verbose lists them]";
        out << "\n";
    }
}

} // namespace kumite::cli
