#pragma once
// The clip dock: the file's annotated clips in a list ("name  (punch right hook high, 30-87)", a mark on those with
// problems), and the selected clip's fields — name, semantics, side, strike kind and height, hit segment, in/out/hit
// frames, mirror — each change one undo command, with the clip's validation messages shown under the fields. The
// kind box offers only the kinds that fit the semantics; kind and height are for strikes only.

#include "annotation_document.h"

#include <QWidget>

class QCheckBox;
class QComboBox;
class QLabel;
class QLineEdit;
class QListWidget;
class QPushButton;
class QSpinBox;

namespace kumite::annotate {

class ClipPanel : public QWidget {
    Q_OBJECT
public:
    ClipPanel(AnnotationDocument& document, QWidget* parent = nullptr);

    // Adds a clip of the current capture around `frame` (the timeline's), selected afterwards.
    void add_clip_at(int frame);
    // Moves the selected clip's hit frame to the one hit_frame_suggest proposes (one undo step).
    void suggest_hit_frame();

private:
    void rebuild_list();
    void refresh_list_item(int index);
    void refresh_fields();
    void refresh_labels(const RawAnnotatedClip* clip); // the kind and height boxes; null: no clip selected
    void edit(ClipField field, const std::function<void(RawAnnotatedClip&)>& change, int session = 0);

    AnnotationDocument& m_document;
    int m_spin_session = 0; // spin box steps merge until editing finishes
    QListWidget* m_list = nullptr;
    QPushButton* m_remove = nullptr;
    QWidget* m_fields = nullptr;
    QLineEdit* m_name = nullptr;
    QLabel* m_source = nullptr;
    QComboBox* m_semantics = nullptr;
    QComboBox* m_side = nullptr;
    QComboBox* m_kind = nullptr;   // item data: the StrikeKind
    QComboBox* m_height = nullptr; // index: the StrikeHeight
    QComboBox* m_segment = nullptr;
    QSpinBox* m_first = nullptr;
    QSpinBox* m_last = nullptr;
    QSpinBox* m_hit = nullptr;
    QCheckBox* m_mirror = nullptr;
    QLabel* m_messages = nullptr;
};

} // namespace kumite::annotate
