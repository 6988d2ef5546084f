#include "issues_panel.h"

#include <QHBoxLayout>
#include <QHeaderView>
#include <QPushButton>
#include <QStyle>
#include <QTreeWidget>
#include <QVBoxLayout>

namespace kumite::annotate {

IssuesPanel::IssuesPanel(AnnotationDocument& document, QWidget* parent) : QWidget(parent), m_document(document) {
    auto* layout = new QVBoxLayout(this);
    m_tree = new QTreeWidget(this);
    m_tree->setHeaderLabels({tr("File"), tr("Line"), tr("Problem")});
    m_tree->setRootIsDecorated(false);
    m_tree->setWordWrap(true);
    m_tree->header()->setStretchLastSection(true);
    layout->addWidget(m_tree);
    auto* clear = new QPushButton(tr("Clear"), this);
    auto* buttons = new QHBoxLayout;
    buttons->addStretch();
    buttons->addWidget(clear);
    layout->addLayout(buttons);
    connect(clear, &QPushButton::clicked, this, [this] { m_document.clear_issues(); });
    connect(&document, &AnnotationDocument::issues_changed, this, &IssuesPanel::rebuild);
    rebuild();
}

void IssuesPanel::rebuild() {
    m_tree->clear();
    for (const Issue& issue : m_document.issues()) {
        auto* item = new QTreeWidgetItem(m_tree);
        item->setIcon(0, style()->standardIcon(issue.severity == IssueSeverity::error ? QStyle::SP_MessageBoxCritical
                                                                                     : QStyle::SP_MessageBoxWarning));
        item->setText(0, issue.file);
        item->setText(1, issue.line > 0 ? QString::number(issue.line) : QString());
        item->setText(2, issue.message);
        item->setToolTip(2, issue.message);
    }
    m_tree->resizeColumnToContents(0);
    m_tree->resizeColumnToContents(1);
    if (m_tree->topLevelItemCount() > 0) m_tree->scrollToItem(m_tree->topLevelItem(m_tree->topLevelItemCount() - 1));
    emit count_changed(m_tree->topLevelItemCount());
}

} // namespace kumite::annotate
