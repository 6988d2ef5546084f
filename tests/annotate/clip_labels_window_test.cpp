// The strike labels in the real window, offscreen: the suggestion list shows each proposal's kind and height and
// Accept carries them into the clip; the Clips dock's Kind box offers only the kinds of the clip's semantics, each
// kind or height change is one undo step, a change of semantics drops a kind it does not allow in the same step,
// and the clip list reads "kick right side low".

#include "main_window.h"
#include "support/test_paths.h"
#include "window_test_support.h"

#include <catch2/catch.hpp>

#include <QComboBox>
#include <QListWidget>
#include <QTreeWidget>

using namespace kumite;
using namespace kumite::annotate;

namespace {

QStringList combo_items(const QComboBox& combo) {
    QStringList items;
    for (int index = 0; index < combo.count(); ++index) items << combo.itemText(index);
    return items;
}

void choose(QComboBox& combo, const QString& text) {
    const int index = combo.findText(text);
    REQUIRE(index >= 0);
    combo.setCurrentIndex(index);
}

} // namespace

TEST_CASE("annotate window: the suggestion list shows each proposal's kind and height, Accept carries them", "[annotate_window]") {
    test::gui_application();
    if (!test::have_captures()) { WARN("captures absent: skipped"); return; }
    const std::filesystem::path root = test::temp_mocap_root("annotate-window-labels-suggest");
    MainWindow window(root, /*interactive=*/false);
    window.show();
    REQUIRE(window.open_path(QString::fromStdString((root / test::k_window_kick_capture).string())));
    test::settle();
    auto* list = window.findChild<QTreeWidget*>("suggestion_list");
    REQUIRE(list);
    const std::vector<StrikeSuggestion>& suggestions = window.document().current_capture()->suggestions;
    REQUIRE(list->topLevelItemCount() == int(suggestions.size()));
    CHECK(list->headerItem()->text(1) == "Kind");
    CHECK(list->headerItem()->text(2) == "Height");
    for (int row = 0; row < list->topLevelItemCount(); ++row) {
        CHECK(list->topLevelItem(row)->text(1) == strike_kind_name(suggestions[size_t(row)].labels.kind));
        CHECK(list->topLevelItem(row)->text(2) == strike_height_name(suggestions[size_t(row)].labels.height));
    }
    REQUIRE(test::click_accept_buttons(window, 10) == int(suggestions.size()));
    AnnotationDocument& document = window.document();
    for (int index = 0; index < document.clip_count(); ++index) {
        const RawAnnotatedClip& clip = document.clip(index);
        bool proposed = false;
        for (const StrikeSuggestion& strike : suggestions) {
            if (strike.hit_frame == clip.hit_frame && strike.segment == clip.segment) {
                proposed = true;
                CHECK(clip.kind == strike.labels.kind);
                CHECK(clip.height == strike.labels.height);
            }
        }
        CHECK(proposed);
    }
}

TEST_CASE("annotate window: the Kind box offers the semantics' kinds, kind and height edits undo and redo", "[annotate_window]") {
    test::gui_application();
    if (!test::have_captures()) { WARN("captures absent: skipped"); return; }
    const std::filesystem::path root = test::temp_mocap_root("annotate-window-labels");
    MainWindow window(root, /*interactive=*/false);
    window.show();
    REQUIRE(window.open_path(QString::fromStdString((root / test::k_window_kick_capture).string())));
    test::settle();
    REQUIRE(test::click_accept_buttons(window, 1) == 1); // a right kick
    AnnotationDocument& document = window.document();
    document.select_clip(0);
    test::settle();
    const RawAnnotatedClip accepted = document.clip(0);
    auto* kind = window.findChild<QComboBox*>("clip_kind");
    auto* height = window.findChild<QComboBox*>("clip_height");
    auto* semantics = window.findChild<QComboBox*>("clip_semantics");
    auto* clips = window.findChild<QListWidget*>("clip_list");
    REQUIRE(kind);
    REQUIRE(height);
    REQUIRE(semantics);
    REQUIRE(clips);
    CHECK(combo_items(*kind) == QStringList{"none", "front", "roundhouse", "side", "other"});
    CHECK(combo_items(*height) == QStringList{"none", "low", "middle", "high"});
    CHECK(kind->isEnabled());
    CHECK(height->isEnabled());
    CHECK(kind->currentText() == strike_kind_name(accepted.kind));
    CHECK(height->currentText() == strike_height_name(accepted.height));

    // Side, then low: one step each, the list and the title follow.
    const int steps = document.undo_stack()->count();
    choose(*kind, accepted.kind == StrikeKind::side ? "front" : "side");
    const StrikeKind chosen = accepted.kind == StrikeKind::side ? StrikeKind::front : StrikeKind::side;
    CHECK(document.clip(0).kind == chosen);
    CHECK(document.undo_stack()->undoText() == "Set Strike Kind");
    choose(*height, accepted.height == StrikeHeight::low ? "high" : "low");
    const StrikeHeight chosen_height = accepted.height == StrikeHeight::low ? StrikeHeight::high : StrikeHeight::low;
    CHECK(document.clip(0).height == chosen_height);
    CHECK(document.undo_stack()->undoText() == "Set Strike Height");
    CHECK(document.undo_stack()->count() == steps + 2);
    CHECK(window.isWindowModified());
    const QString labelled = QStringLiteral("kick right %1 %2").arg(strike_kind_name(chosen), strike_height_name(chosen_height));
    CHECK(clips->item(0)->text().contains(labelled));

    document.undo_stack()->undo();
    document.undo_stack()->undo();
    CHECK(clips_equal(document.clip(0), accepted));
    CHECK(kind->currentText() == strike_kind_name(accepted.kind));
    CHECK(height->currentText() == strike_height_name(accepted.height));
    document.undo_stack()->redo();
    CHECK(document.clip(0).kind == chosen);
    CHECK(kind->currentText() == strike_kind_name(chosen));
    CHECK(clips->item(0)->text().contains(QStringLiteral("kick right %1").arg(strike_kind_name(chosen))));

    // Kick -> punch: a side or front kick's kind goes in the same step, the box now offers the punches' kinds.
    const int before_punch = document.undo_stack()->index(); // index, not count: the new step drops the undone one
    choose(*semantics, "punch");
    emit semantics->textActivated("punch");
    CHECK(document.clip(0).semantics == "punch");
    CHECK(document.clip(0).kind == StrikeKind::none);
    CHECK(document.undo_stack()->index() == before_punch + 1);
    CHECK(document.undo_stack()->count() == before_punch + 1);
    CHECK(document.undo_stack()->undoText() == "Set Semantics");
    CHECK(combo_items(*kind) == QStringList{"none", "straight", "hook", "uppercut", "other"});
    CHECK(kind->currentText() == "none");
    document.undo_stack()->undo();
    CHECK(document.clip(0).semantics == "kick");
    CHECK(document.clip(0).kind == chosen);
    CHECK(kind->currentText() == strike_kind_name(chosen));

    // A rest is no strike: no labels, the boxes off.
    choose(*semantics, "rest");
    emit semantics->textActivated("rest");
    CHECK(document.clip(0).kind == StrikeKind::none);
    CHECK(document.clip(0).height == StrikeHeight::none);
    CHECK_FALSE(kind->isEnabled());
    CHECK_FALSE(height->isEnabled());
    CHECK(document.annotations().validate());
}
