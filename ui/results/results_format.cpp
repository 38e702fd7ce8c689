#include "ui/results/results_format.h"

#include <QComboBox>
#include <QLocale>

namespace imudesk::ui {

using results::Outcome;

QString ResultsFormat::outcome(Outcome o, bool marginal)
{
    switch (o) {
    case Outcome::Pass: return marginal ? tr("PASS (marginal)") : tr("PASS");
    case Outcome::Fail: return tr("FAIL");
    case Outcome::Error: return tr("ERROR");
    case Outcome::Aborted: return tr("ABORTED");
    }
    return {};
}

QColor ResultsFormat::outcomeColour(Outcome o, bool marginal)
{
    // The station tiles' green and red; amber for a marginal pass, orange for the equipment's
    // error, grey for a cancelled module.
    switch (o) {
    case Outcome::Pass: return marginal ? QColor(0x9a, 0x6b, 0x00) : QColor(0x2e, 0x7d, 0x32);
    case Outcome::Fail: return QColor(0xc6, 0x28, 0x28);
    case Outcome::Error: return QColor(0xd8, 0x43, 0x15);
    case Outcome::Aborted: return QColor(0x75, 0x75, 0x75);
    }
    return {};
}

QString ResultsFormat::time(const QDateTime &t)
{
    return t.isValid() ? t.toLocalTime().toString(QStringLiteral("yyyy-MM-dd HH:mm:ss")) : QString();
}

QString ResultsFormat::number(double v)
{
    return QString::number(v, 'g', 6);
}

QString ResultsFormat::range(const std::optional<double> &low, const std::optional<double> &high)
{
    if (low && high)
        return QStringLiteral("%1 … %2").arg(number(*low), number(*high));
    if (high)
        return QStringLiteral("≤ %1").arg(number(*high));
    if (low)
        return QStringLiteral("≥ %1").arg(number(*low));
    return {};
}

QString ResultsFormat::shortText(const QString &text)
{
    QString line = text.left(kMaxShownChars + 1);
    for (QChar &c : line)
        if (c == QLatin1Char('\n') || c == QLatin1Char('\r') || c == QLatin1Char('\t'))
            c = QLatin1Char(' ');
    if (text.size() > kMaxShownChars) {
        line.truncate(kMaxShownChars - 1);
        line += QChar(0x2026);
    }
    return line;
}

QString ResultsFormat::toolTip(const QString &text)
{
    // Rich text so that Qt wraps it; escaped, so that the text is shown, never interpreted.
    return QStringLiteral("<p style='white-space:pre-wrap'>%1</p>").arg(text.toHtmlEscaped());
}

void ResultsFormat::addComboItem(QComboBox *combo, const QString &shown, const QString &value)
{
    combo->addItem(shortText(shown), value);
    combo->setItemData(combo->count() - 1, toolTip(shown), Qt::ToolTipRole);
}

} // namespace imudesk::ui
