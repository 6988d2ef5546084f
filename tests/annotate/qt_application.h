#pragma once
// The annotate tests need a Qt application for timers (autosave) and images; one is made on first use.

#include <QCoreApplication>

#include <filesystem>
#include <functional>

namespace kumite::test {

QCoreApplication& qt_application();

// Runs the event loop until `done` holds or `timeout_ms` passes; returns whether it held.
bool process_events_until(const std::function<bool()>& done, int timeout_ms = 5000);

// A copy of a reference capture in a fresh temp folder (so sidecars never land in the shared captures).
std::filesystem::path copy_capture_to_temp(const std::string& relative_to_mocap_root, const std::string& stem);

} // namespace kumite::test
