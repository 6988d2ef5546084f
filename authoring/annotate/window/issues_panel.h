#pragma once
// The issues dock: every reader, validation, save and bake problem of the session with its file and line, newest
// last, so a bad file is reported instead of crashing the window.

#include "annotation_document.h"

#include <QWidget>

class QTreeWidget;

namespace kumite::annotate {

class IssuesPanel : public QWidget {
    Q_OBJECT
public:
    IssuesPanel(AnnotationDocument& document, QWidget* parent = nullptr);

signals:
    void count_changed(int count);

private:
    void rebuild();

    AnnotationDocument& m_document;
    QTreeWidget* m_tree = nullptr;
};

} // namespace kumite::annotate
