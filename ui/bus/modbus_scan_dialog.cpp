#include "bus/modbus_scan_dialog.h"

#include "device/modbus_session.h"
#include "protocol/modbus/hipnuc_writes.h"

#include <QCheckBox>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QProgressBar>
#include <QPushButton>
#include <QSpinBox>
#include <QTableWidget>
#include <QVBoxLayout>

namespace imudesk::ui {

using device::ModbusScanHit;
using device::ModbusSession;

ModbusScanDialog::ModbusScanDialog(device::ModbusSession *session, QWidget *parent) : QDialog(parent), m_session(session)
{
    setWindowTitle(tr("Scan the Modbus bus"));
    auto *layout = new QVBoxLayout(this);
    auto *form = new QFormLayout;
    m_from = new QSpinBox(this);
    m_from->setRange(1, 247);
    m_to = new QSpinBox(this);
    m_to->setRange(1, 247);
    m_to->setValue(247);
    m_allBauds = new QCheckBox(tr("Every baud rate (4800 to 921600)"), this);
    form->addRow(tr("First node ID"), m_from);
    form->addRow(tr("Last node ID"), m_to);
    form->addRow(QString(), m_allBauds);
    layout->addLayout(form);

    m_progress = new QProgressBar(this);
    m_progress->setRange(0, 1);
    m_progress->setValue(0);
    layout->addWidget(m_progress);

    m_table = new QTableWidget(0, 3, this);
    m_table->setHorizontalHeaderLabels({tr("Node ID"), tr("Baud"), tr("Device")});
    m_table->horizontalHeader()->setStretchLastSection(true);
    m_table->verticalHeader()->hide();
    m_table->setEditTriggers(QAbstractItemView::NoEditTriggers);
    m_table->setSelectionBehavior(QAbstractItemView::SelectRows);
    layout->addWidget(m_table, 1);

    m_status = new QLabel(this);
    m_status->setWordWrap(true);
    layout->addWidget(m_status);

    auto *buttons = new QHBoxLayout;
    m_start = new QPushButton(tr("Start"), this);
    m_cancel = new QPushButton(tr("Cancel scan"), this);
    m_use = new QPushButton(tr("Use"), this);
    auto *close = new QPushButton(tr("Close"), this);
    buttons->addWidget(m_start);
    buttons->addWidget(m_cancel);
    buttons->addStretch(1);
    buttons->addWidget(m_use);
    buttons->addWidget(close);
    layout->addLayout(buttons);
    setScanning(false);

    connect(m_start, &QPushButton::clicked, this, &ModbusScanDialog::start);
    connect(m_cancel, &QPushButton::clicked, this, &ModbusScanDialog::cancel);
    connect(close, &QPushButton::clicked, this, &QDialog::reject);
    auto choose = [this] {
        const int row = m_table->currentRow();
        if (row >= 0)
            Q_EMIT deviceChosen(m_table->item(row, 0)->text().toInt(), m_table->item(row, 1)->text().toInt());
    };
    connect(m_use, &QPushButton::clicked, this, choose);
    connect(m_table, &QTableWidget::cellDoubleClicked, this, choose);
    if (m_session) {
        connect(m_session, &ModbusSession::scanProgress, this, [this](int done, int total) {
            m_progress->setRange(0, std::max(1, total));
            m_progress->setValue(done);
        });
        connect(m_session, &ModbusSession::scanFound, this, &ModbusScanDialog::onFound);
        connect(m_session, &ModbusSession::scanFinished, this, &ModbusScanDialog::onFinished);
    }
}

void ModbusScanDialog::setRange(int firstId, int lastId)
{
    m_from->setValue(firstId);
    m_to->setValue(lastId);
}

void ModbusScanDialog::setAllBauds(bool on)
{
    m_allBauds->setChecked(on);
}

QString ModbusScanDialog::statusText() const
{
    return m_status->text();
}

void ModbusScanDialog::setScanning(bool on)
{
    m_scanning = on;
    m_start->setEnabled(!on && m_session);
    m_cancel->setEnabled(on);
    m_from->setEnabled(!on);
    m_to->setEnabled(!on);
    m_allBauds->setEnabled(!on);
}

void ModbusScanDialog::start()
{
    if (!m_session || m_scanning)
        return;
    if (m_from->value() > m_to->value()) {
        m_status->setText(tr("The first node ID must not be above the last."));
        return;
    }
    device::ModbusScanOptions o;
    o.firstId = m_from->value();
    o.lastId = m_to->value();
    if (m_allBauds->isChecked())
        for (int b : protocol::modbus::HipnucWrites::bauds())
            o.bauds.append(b);
    m_table->setRowCount(0);
    m_progress->setRange(0, 1);
    m_progress->setValue(0);
    m_status->setText(tr("Scanning ..."));
    setScanning(true);
    m_session->scan(o);
}

void ModbusScanDialog::cancel()
{
    if (m_session && m_scanning)
        m_session->cancelScan();
}

void ModbusScanDialog::onFound(const ModbusScanHit &hit)
{
    const int row = m_table->rowCount();
    m_table->insertRow(row);
    m_table->setItem(row, 0, new QTableWidgetItem(QString::number(hit.nodeId)));
    m_table->setItem(row, 1, new QTableWidgetItem(QString::number(hit.baud)));
    m_table->setItem(row, 2, new QTableWidgetItem(hit.summary));
    if (m_table->currentRow() < 0)
        m_table->selectRow(0);
}

void ModbusScanDialog::onFinished(const QList<ModbusScanHit> &hits, bool cancelled)
{
    if (!m_scanning)
        return;
    setScanning(false);
    if (cancelled)
        m_status->setText(tr("Cancelled; %n device(s) found so far.", nullptr, int(hits.size())));
    else if (hits.isEmpty())
        m_status->setText(tr("No device answered. Check the wiring (A/B), the baud rate and parity, or scan every baud rate."));
    else
        m_status->setText(tr("%n device(s) found.", nullptr, int(hits.size())));
}

} // namespace imudesk::ui
