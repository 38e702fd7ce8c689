#include "status_flags_widget.h"

#include "model/main_status.h"

#include <QCoreApplication>
#include <QEvent>
#include <QHBoxLayout>
#include <QLabel>

namespace imudesk::ui {

namespace {

const char *const kSetStyle = "QLabel { background: #2e7d32; color: white; border-radius: 3px; padding: 0 3px; }";
const char *const kClearStyle = "QLabel { background: #e0e0e0; color: #616161; border-radius: 3px; padding: 0 3px; }";
const char *const kUnknownStyle =
    "QLabel { background: transparent; color: #9e9e9e; border: 1px solid #e0e0e0; border-radius: 3px; padding: 0 3px; }";

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
        f.label->setStyleSheet(QString::fromLatin1(state == 1 ? kSetStyle : state == 0 ? kClearStyle : kUnknownStyle));
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
        f.label->setToolTip(tr("<b>%1</b> (bit %2): %3").arg(QString::fromLatin1(info->name)).arg(f.bit).arg(meaning));
    }
    m_title->setToolTip(tr("MAIN_STATUS flags of the latest frame: green = set, grey = clear, outlined = the frame "
                           "carries no status word (firmware before 1.7.0, or another frame type)"));
}

} // namespace imudesk::ui
