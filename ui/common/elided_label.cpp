#include "ui/common/elided_label.h"

#include <QEvent>
#include <QFontMetrics>
#include <QTextLayout>

#include <algorithm>
#include <cmath>

namespace imudesk::ui {

ElidedLabel::ElidedLabel(int maxLines, QWidget *parent) : QLabel(parent), m_maxLines(std::max(1, maxLines))
{
    setTextFormat(Qt::PlainText);
    setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Fixed);
}

void ElidedLabel::setFullText(const QString &text)
{
    if (text == m_full)
        return;
    m_full = text;
    updateGeometry();
    relayout();
}

void ElidedLabel::setExtraToolTip(const QString &extra)
{
    m_extra = extra;
    relayout();
}

QSize ElidedLabel::minimumSizeHint() const
{
    const QFontMetrics fm(font());
    const QMargins m = contentsMargins();
    // As QLabel sets lines: one font height, and a line spacing more for each further line.
    return {fm.horizontalAdvance(QStringLiteral("M…")) + m.left() + m.right(),
            fm.height() + (m_maxLines - 1) * fm.lineSpacing() + m.top() + m.bottom()};
}

QSize ElidedLabel::sizeHint() const
{
    const QFontMetrics fm(font());
    const QMargins m = contentsMargins();
    QSize s = minimumSizeHint();
    s.setWidth(std::max(s.width(), fm.horizontalAdvance(m_full) + m.left() + m.right()));
    return s;
}

void ElidedLabel::resizeEvent(QResizeEvent *event)
{
    QLabel::resizeEvent(event);
    relayout();
}

void ElidedLabel::changeEvent(QEvent *event)
{
    QLabel::changeEvent(event);
    if (event->type() == QEvent::FontChange || event->type() == QEvent::StyleChange)
        relayout();
}

void ElidedLabel::relayout()
{
    const int width = contentsRect().width();
    QString full = m_full;
    full.replace(QLatin1Char('\n'), QLatin1Char(' '));
    const QFontMetrics fm(font());
    QStringList lines;
    if (width <= 0) {
        lines << QString();
    } else if (fm.horizontalAdvance(full) <= width) {
        lines << full;
    } else {
        // Break into lines as a word-wrapped label would; the last line allowed takes the
        // rest, elided.
        QTextLayout layout(full, font());
        QTextOption option;
        option.setWrapMode(QTextOption::WrapAtWordBoundaryOrAnywhere);
        layout.setTextOption(option);
        layout.beginLayout();
        for (;;) {
            QTextLine line = layout.createLine();
            if (!line.isValid())
                break;
            line.setLineWidth(width);
            if (int(lines.size()) + 1 == m_maxLines) {
                lines << fm.elidedText(full.mid(line.textStart()).trimmed(), Qt::ElideRight, width);
                break;
            }
            const QString text = full.mid(line.textStart(), line.textLength()).trimmed();
            lines << (fm.horizontalAdvance(text) <= width ? text : fm.elidedText(text, Qt::ElideRight, width));
        }
        layout.endLayout();
    }
    const QString shown = lines.join(QLatin1Char('\n'));
    QLabel::setText(shown);
    const bool elided = QString(shown).replace(QLatin1Char('\n'), QLatin1Char(' ')).simplified() != full.simplified();
    QStringList tip;
    if (elided)
        tip << m_full;
    if (!m_extra.isEmpty())
        tip << m_extra;
    setToolTip(tip.join(QStringLiteral("\n\n")));
}

} // namespace imudesk::ui
