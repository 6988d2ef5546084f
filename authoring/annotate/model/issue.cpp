#include "issue.h"

#include <QRegularExpression>

namespace kumite::annotate {

Issue issue_from_message(std::string_view message, const QString& fallback_file, IssueSeverity severity) {
    const QString text = QString::fromUtf8(message.data(), static_cast<qsizetype>(message.size()));
    static const QRegularExpression with_line(QStringLiteral("^(.+?):(\\d+): (.*)$"),
                                              QRegularExpression::DotMatchesEverythingOption);
    static const QRegularExpression with_file(QStringLiteral("^([^:]+\\.(?:bvh|json|kdb|autosave)): (.*)$"),
                                              QRegularExpression::DotMatchesEverythingOption |
                                                  QRegularExpression::CaseInsensitiveOption);
    Issue issue;
    issue.severity = severity;
    if (const QRegularExpressionMatch match = with_line.match(text); match.hasMatch()) {
        issue.file = match.captured(1);
        issue.line = match.captured(2).toInt();
        issue.message = match.captured(3);
    } else if (const QRegularExpressionMatch file_match = with_file.match(text); file_match.hasMatch()) {
        issue.file = file_match.captured(1);
        issue.message = file_match.captured(2);
    } else {
        issue.file = fallback_file;
        issue.message = text;
    }
    return issue;
}

} // namespace kumite::annotate
