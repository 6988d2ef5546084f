#pragma once
// A picture to judge a strike by eye: the frames around the contact in two rows, seen from the side and from the
// front, drawn with the viewer's capsule renderer (QPainter, so it works offscreen): the character, the target,
// the hit point's path (yellow up to the contact, blue after it), frame numbers, the contact frame framed in red.
// Used by `kumite adapt --filmstrip` and the annotation window's preview. Needs a QGuiApplication.

#include "scene.h"

#include "kumite/runtime/strike_playback.h"

#include <QImage>
#include <QString>

namespace kumite::view {

struct FilmstripOptions {
    int frames_before = 12; // around the contact, every `frame_step` frames (the contact always included)
    int frames_after = 15;
    int frame_step = 3;
    int cell_width_px = 190;
    int cell_height_px = 290;
};

// Frame `frame` of a played strike as a Scene: the character, the target, the effector, and the hit point's path
// from `first_path_frame` (yellow to the contact, blue after it). What the filmstrip's cells and the annotation
// window's preview draw.
void strike_frame_scene(const StrikePlayback& playback, int frame, int first_path_frame, Scene& scene);

// The frame indices of `playback.motion` a filmstrip shows.
std::vector<int> filmstrip_frames(const StrikePlayback& playback, const FilmstripOptions& options = {});

QImage strike_filmstrip_render(const StrikePlayback& playback, const QString& title, const FilmstripOptions& options = {});

} // namespace kumite::view

namespace kumite::view {

// Renders the filmstrip and writes it as PNG through a temporary file (the old file, if any, stays on failure).
// Creates an offscreen QGuiApplication when the process has none, so it needs no display.
Result<void> strike_filmstrip_save(const StrikePlayback& playback, const QString& title, const std::string& png_path,
                                   const FilmstripOptions& options = {});

} // namespace kumite::view
