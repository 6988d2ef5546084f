#include "kumite/runtime/dtrack.h"

#include <charconv>
#include <cmath>

namespace kumite {
namespace {

// Reads one line's tokens: numbers, '[' and ']' groups, without allocating.
class LineReader {
public:
    explicit LineReader(std::string_view line) : m_text(line) {}

    void skip_blanks() {
        while (m_at < m_text.size() && (m_text[m_at] == ' ' || m_text[m_at] == '\t')) ++m_at;
    }
    bool at_end() {
        skip_blanks();
        return m_at >= m_text.size();
    }
    bool expect(char c) {
        skip_blanks();
        if (m_at < m_text.size() && m_text[m_at] == c) {
            ++m_at;
            return true;
        }
        return false;
    }
    bool number(double& out) {
        skip_blanks();
        const char* begin = m_text.data() + m_at;
        const char* end = m_text.data() + m_text.size();
        const auto [next, error] = std::from_chars(begin, end, out);
        if (error != std::errc() || !std::isfinite(out)) return false;
        m_at += static_cast<std::size_t>(next - begin);
        return true;
    }
    bool integer(long long& out) {
        double value = 0.0;
        if (!number(value) || value != std::floor(value) || std::abs(value) > 1e15) return false;
        out = static_cast<long long>(value);
        return true;
    }
    // "[a b c ...]" with exactly `count` numbers, or with one of two counts (`count`, `alternative`).
    int group(double* out, int count, int alternative = -1) {
        if (!expect('[')) return -1;
        int read = 0;
        const int most = std::max(count, alternative);
        while (read < most && !(skip_blanks(), m_at < m_text.size() && m_text[m_at] == ']')) {
            if (!number(out[read])) return -1;
            ++read;
        }
        if (!expect(']')) return -1;
        return read == count || read == alternative ? read : -1;
    }

private:
    std::string_view m_text;
    std::size_t m_at = 0;
};

DtrackParseResult fail(int line, const char* what) { return {false, line, what}; }

bool valid_id(double id) { return id >= 0.0 && id <= 1e6 && id == std::floor(id); }

} // namespace

const DtrackBody* DtrackFrame::body(int id) const {
    for (int i = 0; i < body_count; ++i) {
        if (bodies[i].id == id) return &bodies[i];
    }
    return nullptr;
}

DtrackParseResult dtrack_parse(std::string_view datagram, DtrackFrame& frame) {
    frame.has_frame_number = frame.has_timestamp = false;
    frame.body_count = frame.marker_count = frame.bodies_dropped = frame.markers_dropped = 0;
    if (datagram.empty()) return fail(0, "empty datagram");
    int line_number = 0;
    bool any = false;
    std::size_t start = 0;
    while (start < datagram.size()) {
        std::size_t end = datagram.find('\n', start);
        if (end == std::string_view::npos) end = datagram.size();
        std::string_view line = datagram.substr(start, end - start);
        start = end + 1;
        ++line_number;
        if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
        if (line.find('\0') != std::string_view::npos) return fail(line_number, "a NUL byte in the datagram");
        const std::size_t blank = line.find_first_of(" \t");
        const std::string_view type = line.substr(0, blank);
        LineReader reader(blank == std::string_view::npos ? std::string_view() : line.substr(blank));
        if (type.empty()) {
            if (!reader.at_end()) return fail(line_number, "a line without a type");
            continue;
        }
        if (type == "fr") {
            long long number = 0;
            if (!reader.integer(number) || number < 0 || !reader.at_end()) return fail(line_number, "fr: expected a frame number");
            frame.has_frame_number = true;
            frame.frame_number = static_cast<std::uint64_t>(number);
        } else if (type == "ts") {
            if (!reader.number(frame.timestamp_s) || !reader.at_end()) return fail(line_number, "ts: expected a timestamp");
            frame.has_timestamp = true;
        } else if (type == "6d") {
            long long count = 0;
            if (!reader.integer(count) || count < 0 || count > 1000) return fail(line_number, "6d: expected a body count");
            for (long long i = 0; i < count; ++i) {
                double head[2], position[6], matrix[9];
                if (reader.group(head, 2) < 0) return fail(line_number, "6d: expected [id quality]");
                if (reader.group(position, 3, 6) < 0) return fail(line_number, "6d: expected [x y z]");
                if (reader.group(matrix, 9) < 0) return fail(line_number, "6d: expected a 3x3 rotation [b0 .. b8]");
                if (!valid_id(head[0])) return fail(line_number, "6d: a body id is not a whole number from 0 to 1e6");
                if (frame.body_count == k_dtrack_max_bodies) {
                    ++frame.bodies_dropped;
                    continue;
                }
                DtrackBody& body = frame.bodies[frame.body_count++];
                body.id = static_cast<int>(head[0]);
                body.quality = head[1];
                body.position_mm = Eigen::Vector3d(position[0], position[1], position[2]);
                for (int column = 0; column < 3; ++column) {
                    for (int row = 0; row < 3; ++row) body.rotation(row, column) = matrix[column * 3 + row];
                }
            }
            if (!reader.at_end()) return fail(line_number, "6d: more bodies than its count");
        } else if (type == "3d") {
            long long count = 0;
            if (!reader.integer(count) || count < 0 || count > 10000) return fail(line_number, "3d: expected a marker count");
            for (long long i = 0; i < count; ++i) {
                double head[2], position[3];
                if (reader.group(head, 2) < 0) return fail(line_number, "3d: expected [id quality]");
                if (reader.group(position, 3) < 0) return fail(line_number, "3d: expected [x y z]");
                if (!valid_id(head[0])) return fail(line_number, "3d: a marker id is not a whole number from 0 to 1e6");
                if (frame.marker_count == k_dtrack_max_markers) {
                    ++frame.markers_dropped;
                    continue;
                }
                DtrackMarker& marker = frame.markers[frame.marker_count++];
                marker.id = static_cast<int>(head[0]);
                marker.quality = head[1];
                marker.position_mm = Eigen::Vector3d(position[0], position[1], position[2]);
            }
            if (!reader.at_end()) return fail(line_number, "3d: more markers than its count");
        } else {
            for (char c : type) {
                if (!((c >= 'a' && c <= 'z') || (c >= '0' && c <= '9'))) return fail(line_number, "not a DTrack line");
            }
            continue; // another line type: skipped
        }
        any = true;
    }
    if (!any) return fail(line_number, "no fr, ts, 6d or 3d line");
    return {};
}

} // namespace kumite
