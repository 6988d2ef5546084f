#include "clip_labels.h"

#include <QStringList>

namespace kumite::annotate {

std::vector<StrikeKind> strike_kinds_offered(std::string_view semantics) {
    std::vector<StrikeKind> kinds{StrikeKind::none};
    for (int kind = 1; kind < k_strike_kind_count; ++kind) {
        if (strike_kind_fits(semantics, static_cast<StrikeKind>(kind))) kinds.push_back(static_cast<StrikeKind>(kind));
    }
    return kinds;
}

RawAnnotatedClip clip_with_semantics(RawAnnotatedClip clip, const std::string& semantics) {
    clip.semantics = semantics;
    if (clip.is_strike()) {
        if (!clip.hit_frame) clip.hit_frame = (clip.first_frame + clip.last_frame) / 2; // a strike needs one
        if (!strike_kind_fits(clip.semantics, clip.kind)) clip.kind = StrikeKind::none;
    } else {
        clip.kind = StrikeKind::none;
        clip.height = StrikeHeight::none;
    }
    return clip;
}

QString strike_labels_text(StrikeKind kind, StrikeHeight height) {
    QStringList words;
    if (kind != StrikeKind::none) words << QString::fromLatin1(strike_kind_name(kind));
    if (height != StrikeHeight::none) words << QString::fromLatin1(strike_height_name(height));
    return words.join(QLatin1Char(' '));
}

QString clip_labels_text(const RawAnnotatedClip& clip) {
    QStringList words{QString::fromStdString(clip.semantics)};
    if (clip.side == Side::left) words << QStringLiteral("left");
    if (clip.side == Side::right) words << QStringLiteral("right");
    if (const QString labels = strike_labels_text(clip.kind, clip.height); !labels.isEmpty()) words << labels;
    return words.join(QLatin1Char(' '));
}

} // namespace kumite::annotate
