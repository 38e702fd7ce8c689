#include "bus/register_browser.h"

#include "device/modbus_session.h"
#include "protocol/modbus/register_block.h"

#include <QComboBox>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QPlainTextEdit>
#include <QPushButton>
#include <QSpinBox>
#include <QTableView>
#include <QVBoxLayout>

namespace imudesk::ui {

using device::ModbusRegisterReply;
using device::ModbusSession;
using protocol::modbus::RegisterBlock;
using protocol::modbus::RegisterMap;

RegisterBrowser::RegisterBrowser(device::ModbusSession *session, QWidget *parent)
    : QDockWidget(tr("Modbus registers"), parent), m_session(session), m_refresh(this)
{
    setObjectName(QStringLiteral("registerBrowserDock"));
    auto *body = new QWidget(this);
    auto *layout = new QVBoxLayout(body);

    m_view = new QTableView(body);
    m_view->setModel(&m_model);
    m_view->setSelectionBehavior(QAbstractItemView::SelectRows);
    m_view->setEditTriggers(QAbstractItemView::DoubleClicked | QAbstractItemView::EditKeyPressed);
    m_view->verticalHeader()->hide();
    m_view->horizontalHeader()->setStretchLastSection(true);
    layout->addWidget(m_view, 1);

    m_status = new QLabel(body);
    m_status->setWordWrap(true);
    layout->addWidget(m_status);

    auto *raw = new QHBoxLayout;
    m_function = new QComboBox(body);
    m_function->addItem(tr("03 Read holding registers"), 3);
    m_function->addItem(tr("06 Write single register"), 6);
    m_address = new QSpinBox(body);
    m_address->setRange(0, 0xFFFF);
    m_address->setDisplayIntegerBase(16);
    m_address->setPrefix(QStringLiteral("0x"));
    m_address->setToolTip(tr("Register address"));
    m_countOrValue = new QSpinBox(body);
    m_send = new QPushButton(tr("Send"), body);
    raw->addWidget(m_function);
    raw->addWidget(new QLabel(tr("Address"), body));
    raw->addWidget(m_address);
    raw->addWidget(m_countOrValue);
    raw->addWidget(m_send);
    layout->addLayout(raw);
    m_rawResult = new QPlainTextEdit(body);
    m_rawResult->setReadOnly(true);
    m_rawResult->setMaximumBlockCount(200);
    m_rawResult->setMaximumHeight(90);
    layout->addWidget(m_rawResult);
    setWidget(body);
    updateRawInputs();

    m_model.setMap(RegisterMap::hipnuc(model::ManualEdition::V171));
    m_refresh.setInterval(kDefaultRefreshMs);
    connect(&m_refresh, &QTimer::timeout, this, [this] {
        if (isVisible())
            refresh();
    });
    m_refresh.start();

    connect(m_function, &QComboBox::currentIndexChanged, this, &RegisterBrowser::updateRawInputs);
    connect(m_send, &QPushButton::clicked, this, &RegisterBrowser::onSendClicked);
    connect(&m_model, &models::RegisterTableModel::writeRequested, this, [this](int address, int value) {
        if (!m_session)
            return;
        m_writeIds.insert(m_session->writeRegister(address, value, true));
        showStatus(tr("Writing %1 to register 0x%2 ...").arg(value).arg(address, 4, 16, QLatin1Char('0')), false);
    });
    connect(&m_model, &models::RegisterTableModel::writeRefused, this, [this](const QString &m) { showStatus(m, true); });
    if (m_session) {
        connect(m_session, &ModbusSession::registersRead, this, &RegisterBrowser::onRegistersRead);
        connect(m_session, &ModbusSession::writeFinished, this, &RegisterBrowser::onWriteFinished);
        connect(m_session, &ModbusSession::identityChanged, this, &RegisterBrowser::onIdentity);
    }
}

void RegisterBrowser::setMap(const RegisterMap &map)
{
    if (m_model.map() != &map)
        m_model.setMap(map);
}

void RegisterBrowser::setRefreshInterval(int ms)
{
    m_refresh.setInterval(std::max(50, ms));
}

QString RegisterBrowser::statusText() const
{
    return m_status->text();
}

QString RegisterBrowser::rawResultText() const
{
    return m_rawResult->toPlainText();
}

void RegisterBrowser::onIdentity(const model::DeviceIdentity &identity)
{
    if (m_session && m_session->linkKind().startsWith(QLatin1String("HEC495")))
        setMap(RegisterMap::hec495());
    else
        setMap(RegisterMap::hipnuc(identity.firmware ? identity.edition() : model::ManualEdition::V171));
}

void RegisterBrowser::refresh()
{
    if (!m_session || m_session->state() != device::SessionState::Connected || !m_tableReads.isEmpty())
        return; // one round at a time: a slow bus is never flooded
    for (const auto &r : m_model.readRanges())
        m_tableReads.insert(m_session->readRegisters(r.start, r.count));
}

void RegisterBrowser::onRegistersRead(const ModbusRegisterReply &reply)
{
    if (m_tableReads.remove(reply.id)) {
        if (reply.ok)
            m_model.setBlock(RegisterBlock(uint16_t(reply.start), std::vector<uint16_t>(reply.values.begin(), reply.values.end())));
        else
            showStatus(reply.message, true);
        return;
    }
    if (!m_rawIds.remove(reply.id))
        return;
    if (!reply.ok) {
        m_rawResult->appendPlainText(reply.message);
        return;
    }
    QStringList words;
    for (quint16 w : reply.values)
        words << QStringLiteral("%1").arg(w, 4, 16, QLatin1Char('0')).toUpper();
    m_rawResult->appendPlainText(QStringLiteral("03 @0x%1: %2").arg(reply.start, 4, 16, QLatin1Char('0')).arg(words.join(QLatin1Char(' '))));
    m_model.setBlock(RegisterBlock(uint16_t(reply.start), std::vector<uint16_t>(reply.values.begin(), reply.values.end())));
}

void RegisterBrowser::onWriteFinished(const ModbusRegisterReply &reply)
{
    const bool raw = m_rawIds.remove(reply.id);
    if (!raw && !m_writeIds.remove(reply.id))
        return;
    if (raw)
        m_rawResult->appendPlainText(QStringLiteral("06 @0x%1: %2").arg(reply.start, 4, 16, QLatin1Char('0')).arg(reply.message));
    showStatus(reply.message, !reply.ok);
    refresh();
}

void RegisterBrowser::showStatus(const QString &text, bool error)
{
    m_status->setText(text);
    m_status->setProperty("error", error);
    m_status->setStyleSheet(error ? QStringLiteral("color: #b00020;") : QString());
}

void RegisterBrowser::sendRawRequest(int function, int address, int countOrValue)
{
    if (!m_session) {
        m_rawResult->appendPlainText(tr("Not connected."));
        return;
    }
    if (function == 3)
        m_rawIds.insert(m_session->readRegisters(address, countOrValue));
    else if (function == 6)
        m_rawIds.insert(m_session->writeRegister(address, countOrValue, false));
    else
        m_rawResult->appendPlainText(tr("Only functions 03 and 06 are supported by these devices."));
}

void RegisterBrowser::onSendClicked()
{
    sendRawRequest(m_function->currentData().toInt(), m_address->value(), m_countOrValue->value());
}

void RegisterBrowser::updateRawInputs()
{
    if (m_function->currentData().toInt() == 3) {
        m_countOrValue->setRange(1, 125);
        m_countOrValue->setPrefix(tr("count "));
    } else {
        m_countOrValue->setRange(0, 0xFFFF);
        m_countOrValue->setPrefix(tr("value "));
    }
}

} // namespace imudesk::ui
