#pragma once
// One entry of the window's issues panel: a reader or validation error split into file, line and message so the
// animator sees where to look. Messages follow the project's "FILE:LINE: what" convention when they have a line.

#include <QString>

#include <string_view>

namespace kumite::annotate {

enum class IssueSeverity { error, warning };

struct Issue {
    IssueSeverity severity = IssueSeverity::error;
    QString file;    // may be empty
    int line = 0;    // 0: no line
    QString message; // without the "FILE:LINE: " prefix
};

// Splits "path/to/file.bvh:12: expected ..." into its parts; other messages keep `fallback_file` and line 0.
Issue issue_from_message(std::string_view message, const QString& fallback_file = {},
                         IssueSeverity severity = IssueSeverity::error);

} // namespace kumite::annotate
