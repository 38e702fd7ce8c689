#pragma once
#include <QLabel>
#include <QString>

namespace imudesk::ui {

// A label that shows as much of its text as fits in up to maxLines lines, the last one
// elided, and the whole text in its tooltip when anything was left out; it never asks for
// more width than it gets, so a long serial number or failure cannot widen the grid.
class ElidedLabel : public QLabel {
public:
    ElidedLabel(int maxLines, QWidget *parent);

    void setFullText(const QString &text);
    const QString &fullText() const { return m_full; }
    // Shown in the tooltip after the full text (or alone when nothing is elided).
    void setExtraToolTip(const QString &extra);

    QSize minimumSizeHint() const override;
    QSize sizeHint() const override;

protected:
    void resizeEvent(QResizeEvent *event) override;
    void changeEvent(QEvent *event) override;

private:
    void relayout();

    int m_maxLines;
    QString m_full, m_extra;
};

} // namespace imudesk::ui
