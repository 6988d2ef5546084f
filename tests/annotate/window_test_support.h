#pragma once
// What the window tests share: one QApplication (offscreen, never destroyed), the event loop run for a while, a
// mocap root in a temp folder holding the kick capture, and the suggestions' Accept buttons clicked.

#include <QApplication>
#include <QWidget>

#include <filesystem>
#include <string>

namespace kumite::test {

inline const std::string k_window_kick_capture = "bandai-namco-1/dataset-1_kick_normal_001.bvh";

QApplication& gui_application();
void settle(int ms = 50);                                      // runs events for `ms`, deferred deletes included
std::filesystem::path temp_mocap_root(const std::string& stem); // autosaves never land in the shared captures
int click_accept_buttons(QWidget& window, int at_most);          // how many it clicked
bool have_captures();

} // namespace kumite::test
