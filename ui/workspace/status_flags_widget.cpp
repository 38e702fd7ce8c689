#include "workspace/status_flags_widget.h"

#include "model/main_status.h"

#include <QCoreApplication>
#include <QEvent>
#include <QHBoxLayout>
#include <QLabel>

namespace imudesk::ui {

namespace {

// A set flag is coloured by what it means: green good news, blue an indication, amber a
// warning about the data. A clear flag is grey; outlined when the frame has no status word.
const char *const kGoodStyle = "QLabel { background: #2e7d32; color: white; border-radius: 3px; padding: 0 3px; }";
const char *const kInfoStyle = "QLabel { background: #1565c0; color: white; border-radius: 3px; padding: 0 3px; }";
const char *const kWarningStyle =
    "QLabel { background: #ef6c00; color: black; border-radius: 3px; padding: 0 3px; font-weight: bold; }";
const char *const kClearStyle = "QLabel { background: #e0e0e0; color: #616161; border-radius: 3px; padding: 0 3px; }";
const char *const kUnknownStyle =
    "QLabel { background: transparent; color: #9e9e9e; border: 1px solid #e0e0e0; border-radius: 3px; padding: 0 3px; }";

const char *setFlagStyle(model::FlagSeverity severity)
{
    switch (severity) {
    case model::FlagSeverity::Good: return kGoodStyle;
    case model::FlagSeverity::Information: return kInfoStyle;
    case model::FlagSeverity::Warning: return kWarningStyle;
    }
    return kInfoStyle;
}

const model::StatusFlagInfo *infoOf(int bit)
{
    for (const auto &d : model::MainStatus::definitions())
        if (d.bit == bit)
            return &d;
    return nullptr;
}

} // namespace

StatusFlagsWidget::StatusFlagsWidget(QWidget *parent) : QWidget(parent)
{
    auto *layout = new QHBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->setSpacing(2);
    m_title = new QLabel(this);
    layout->addWidget(m_title);
    QFont small = font();
    small.setPointSizeF(small.pointSizeF() * 0.85);
    for (const auto &d : model::MainStatus::definitions()) {
        Flag f;
        f.bit = d.bit;
        f.label = new QLabel(QString::fromLatin1(d.name), this);
        f.label->setObjectName(QStringLiteral("flag_%1").arg(QString::fromLatin1(d.name)));
        f.label->setFont(small);
        layout->addWidget(f.label);
        m_flags.push_back(f);
    }
    retranslateUi();
    updateLabels(true);
}

void StatusFlagsWidget::setStatus(std::optional<quint16> raw)
{
    if (raw == m_status)
        return;
    m_status = raw;
    updateLabels(false);
}

QString StatusFlagsWidget::flagText(int bit) const
{
    for (const auto &f : m_flags)
        if (f.bit == bit)
            return f.label->text();
    return QString();
}

QString StatusFlagsWidget::flagToolTip(int bit) const
{
    for (const auto &f : m_flags)
        if (f.bit == bit)
            return f.label->toolTip();
    return QString();
}

void StatusFlagsWidget::changeEvent(QEvent *event)
{
    if (event->type() == QEvent::LanguageChange)
        retranslateUi();
    QWidget::changeEvent(event);
}

void StatusFlagsWidget::updateLabels(bool force)
{
    for (auto &f : m_flags) {
        const int state = !m_status ? 2 : ((*m_status >> f.bit) & 1u) ? 1 : 0;
        if (!force && state == f.shown)
            continue;
        f.shown = state;
        const auto *info = infoOf(f.bit);
        const char *style = state == 1 ? setFlagStyle(info ? info->severity : model::FlagSeverity::Information)
            : state == 0               ? kClearStyle
                                       : kUnknownStyle;
        f.label->setStyleSheet(QString::fromLatin1(style));
    }
}

void StatusFlagsWidget::retranslateUi()
{
    m_title->setText(tr("Status:"));
    for (auto &f : m_flags) {
        const auto *info = infoOf(f.bit);
        if (!info)
            continue;
        const QString meaning = QCoreApplication::translate("imudesk::model::MainStatus", info->meaning);
        QString kind;
        switch (info->severity) {
        case model::FlagSeverity::Good: kind = tr("good news when set"); break;
        case model::FlagSeverity::Information: kind = tr("information"); break;
        case model::FlagSeverity::Warning: kind = tr("warning when set"); break;
        }
        f.label->setToolTip(tr("<b>%1</b> (bit %2, %3): %4<br><i>Source: %5</i>")
                                .arg(QString::fromLatin1(info->name))
                                .arg(f.bit)
                                .arg(kind, meaning,
                                     QCoreApplication::translate("imudesk::model::MainStatus", info->source)));
    }
    m_title->setToolTip(tr("MAIN_STATUS flags of the latest frame. Set: amber = a warning about the data, blue = "
                           "information, green = good news (magnetometer aiding the heading). Grey = clear; outlined = "
                           "the frame carries no status word (firmware before 1.7.0, or another frame type)"));
}

} // namespace imudesk::ui
