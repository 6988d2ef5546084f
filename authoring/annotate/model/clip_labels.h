#pragma once
// A strike clip's kind and height labels as the window edits them: the kinds its semantics offers, a change of
// semantics that keeps the labels valid (in the same undo step), and the short text the lists show.

#include "kumite/formats/annotation_file.h"

#include <QString>

#include <string>
#include <string_view>
#include <vector>

namespace kumite::annotate {

// `none` first, then the kinds that fit `semantics` (strike_kind_fits) in enum order: punch -> none, straight,
// hook, uppercut, other; kick -> none, front, roundhouse, side, other; anything else -> none, other.
std::vector<StrikeKind> strike_kinds_offered(std::string_view semantics);

// `clip` with `semantics` instead: a strike gets a hit frame (mid-range) when it has none, a kind that does not fit
// the new semantics becomes none (a hook stops being a kick's kind), and a clip that is no longer a strike loses
// both labels (the file allows them on strikes only).
RawAnnotatedClip clip_with_semantics(RawAnnotatedClip clip, const std::string& semantics);

// "punch right hook high": semantics, then side, kind and height where they are set.
QString clip_labels_text(const RawAnnotatedClip& clip);
QString strike_labels_text(StrikeKind kind, StrikeHeight height); // "hook high", "" when both are none

} // namespace kumite::annotate
