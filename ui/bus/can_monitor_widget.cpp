#include "bus/can_monitor_widget.h"

#include <QCheckBox>
#include <QFileDialog>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QRegularExpression>
#include <QTableView>
#include <QToolButton>
#include <QVBoxLayout>

namespace imudesk::ui {

using protocol::can::CanFrame;

CanMonitorWidget::CanMonitorWidget(QWidget *parent)
    : QWidget(parent), m_model(new models::CanFrameMonitorModel(this)), m_table(new QTableView(this)),
      m_filter(new QLineEdit(this)), m_pause(new QToolButton(this)), m_clear(new QPushButton(tr("Clear"), this)),
      m_export(new QPushButton(tr("Export CSV…"), this)), m_sendId(new QLineEdit(this)), m_sendData(new QLineEdit(this)),
      m_sendExt(new QCheckBox(tr("Extended"), this)), m_sendFd(new QCheckBox(tr("FD"), this)),
      m_send(new QPushButton(tr("Send"), this)), m_status(new QLabel(this))
{
    m_filter->setPlaceholderText(tr("Filter: ID or meaning"));
    m_filter->setClearButtonEnabled(true);
    m_pause->setText(tr("Pause"));
    m_pause->setCheckable(true);
    m_table->setModel(m_model);
    m_table->setSelectionBehavior(QAbstractItemView::SelectRows);
    m_table->verticalHeader()->hide();
    m_table->horizontalHeader()->setStretchLastSection(true);
    m_table->setAlternatingRowColors(true);
    m_sendId->setPlaceholderText(tr("ID (hex)"));
    m_sendId->setMaximumWidth(110);
    m_sendData->setPlaceholderText(tr("data (hex bytes)"));

    auto *top = new QHBoxLayout;
    top->addWidget(m_filter, 1);
    top->addWidget(m_pause);
    top->addWidget(m_clear);
    top->addWidget(m_export);
    auto *send = new QHBoxLayout;
    send->addWidget(m_sendId);
    send->addWidget(m_sendData, 1);
    send->addWidget(m_sendExt);
    send->addWidget(m_sendFd);
    send->addWidget(m_send);
    auto *lay = new QVBoxLayout(this);
    lay->setContentsMargins(2, 2, 2, 2);
    lay->addLayout(top);
    lay->addWidget(m_table, 1);
    lay->addLayout(send);
    lay->addWidget(m_status);

    connect(m_filter, &QLineEdit::textChanged, m_model, &models::CanFrameMonitorModel::setFilter);
    connect(m_pause, &QToolButton::toggled, this, [this](bool on) {
        m_model->setPaused(on);
        updateStatus();
    });
    connect(m_clear, &QPushButton::clicked, this, [this] {
        m_model->clear();
        updateStatus();
    });
    connect(m_export, &QPushButton::clicked, this, &CanMonitorWidget::onExport);
    connect(m_send, &QPushButton::clicked, this, &CanMonitorWidget::onSend);
    connect(m_sendData, &QLineEdit::returnPressed, this, &CanMonitorWidget::onSend);
    updateStatus();
}

void CanMonitorWidget::addEvents(const device::CanFrameEvents &events)
{
    m_model->addEvents(events);
    updateStatus();
}

void CanMonitorWidget::updateStatus()
{
    QString s = tr("%1 frames, %2 IDs").arg(m_model->totalFrames()).arg(m_model->rowCount());
    if (m_model->isPaused())
        s += tr(" — paused (%1 frames not shown)").arg(m_model->framesWhilePaused());
    if (m_model->framesOverLimit())
        s += tr(" — %1 frames of IDs beyond the %2-row limit").arg(m_model->framesOverLimit()).arg(m_model->maxRows());
    m_status->setText(s);
}

std::optional<CanFrame> CanMonitorWidget::parseFrame(const QString &idText, const QString &dataText, bool extended, bool fd,
                                                     QString *error)
{
    bool ok = false;
    QString idClean = idText.trimmed();
    if (idClean.startsWith(QLatin1String("0x"), Qt::CaseInsensitive))
        idClean = idClean.mid(2);
    if (idClean.endsWith(QLatin1Char('h'), Qt::CaseInsensitive))
        idClean.chop(1);
    const uint id = idClean.toUInt(&ok, 16);
    if (!ok || id > (extended ? 0x1FFFFFFFu : 0x7FFu)) {
        *error = extended ? tr("The ID must be hexadecimal, 0 to 1FFFFFFF.") : tr("The ID must be hexadecimal, 0 to 7FF (tick Extended for 29-bit IDs).");
        return std::nullopt;
    }
    QString hex = dataText;
    hex.remove(QRegularExpression(QStringLiteral("[\\s,:]")));
    if (hex.size() % 2 || !QRegularExpression(QStringLiteral("^[0-9A-Fa-f]*$")).match(hex).hasMatch()) {
        *error = tr("The data must be pairs of hexadecimal digits, e.g. 2B 00 18 05 0A 00 00 00.");
        return std::nullopt;
    }
    const QByteArray bytes = QByteArray::fromHex(hex.toLatin1());
    if (bytes.size() > (fd ? 64 : 8)) {
        *error = fd ? tr("A CAN FD frame carries at most 64 bytes.") : tr("A classic CAN frame carries at most 8 bytes (tick FD for more).");
        return std::nullopt;
    }
    return CanFrame::fromBytes(id, extended, reinterpret_cast<const uint8_t *>(bytes.constData()), size_t(bytes.size()), fd);
}

void CanMonitorWidget::onSend()
{
    QString error;
    const auto f = parseFrame(m_sendId->text(), m_sendData->text(), m_sendExt->isChecked(), m_sendFd->isChecked(), &error);
    if (!f) {
        m_status->setText(error);
        return;
    }
    Q_EMIT sendFrameRequested(*f);
}

bool CanMonitorWidget::exportCsv(const QString &path)
{
    QString error;
    if (!m_model->exportCsv(path, &error)) {
        m_status->setText(error);
        return false;
    }
    m_status->setText(tr("Saved %1 IDs to %2").arg(m_model->rowCount()).arg(path));
    return true;
}

void CanMonitorWidget::onExport()
{
    const QString path = QFileDialog::getSaveFileName(this, tr("Export CAN frames"), QString(), tr("CSV files (*.csv)"));
    if (!path.isEmpty())
        exportCsv(path);
}

} // namespace imudesk::ui
