#include "bus/bus_connect_dialog.h"

#include "device/can_session.h"
#include "protocol/can/can_setting_catalog.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDialogButtonBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QSerialPortInfo>
#include <QSpinBox>
#include <QVBoxLayout>

namespace imudesk::ui {

using protocol::modbus::DeviceKind;

namespace {

QDialogButtonBox *addButtons(QDialog *dialog, QVBoxLayout *layout)
{
    auto *buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, dialog);
    buttons->button(QDialogButtonBox::Ok)->setText(QCoreApplication::translate("imudesk::ui::BusConnect", "Connect"));
    QObject::connect(buttons, &QDialogButtonBox::accepted, dialog, &QDialog::accept);
    QObject::connect(buttons, &QDialogButtonBox::rejected, dialog, &QDialog::reject);
    layout->addWidget(buttons);
    return buttons;
}

constexpr const char *kSimulatedKey = "sim:";

} // namespace

// ---------------------------------------------------------------- Modbus

ModbusConnectDialog::ModbusConnectDialog(QWidget *parent) : QDialog(parent)
{
    setWindowTitle(tr("Connect over Modbus RTU"));
    setObjectName(QStringLiteral("modbusConnectDialog"));
    auto *form = new QFormLayout;
    m_port = new QComboBox(this);
    m_port->setToolTip(tr("The RS-485 adapter's serial port, or a simulated device"));
    for (const QSerialPortInfo &info : QSerialPortInfo::availablePorts())
        m_port->addItem(info.description().isEmpty() ? info.systemLocation()
                                                     : tr("%1 (%2)").arg(info.systemLocation(), info.description()),
                        info.systemLocation());
    m_port->addItem(tr("Simulated HI14 (Modbus)"), QString::fromLatin1(kSimulatedKey) + QStringLiteral("hipnuc"));
    m_port->addItem(tr("Simulated HEC495 (Modbus)"), QString::fromLatin1(kSimulatedKey) + QStringLiteral("hec495"));
    form->addRow(tr("&Port:"), m_port);
    m_kind = new QComboBox(this);
    m_kind->addItem(tr("HiPNUC module"), int(DeviceKind::Hipnuc));
    m_kind->addItem(tr("HEC495 compass"), int(DeviceKind::Hec495));
    m_kind->setToolTip(tr("Which register map the device has"));
    form->addRow(tr("&Device:"), m_kind);
    m_node = new QSpinBox(this);
    m_node->setRange(1, 247);
    m_node->setToolTip(tr("Modbus node ID (slave address), 1 to 247; HiPNUC modules default to 80, the HEC495 to 1"));
    form->addRow(tr("&Node ID:"), m_node);
    m_baud = new QComboBox(this);
    for (int b : {2400, 4800, 9600, 19200, 38400, 57600, 115200, 230400, 460800, 921600})
        m_baud->addItem(QString::number(b), b);
    m_baud->setToolTip(tr("Baud rate of the RS-485 bus"));
    form->addRow(tr("&Baud rate:"), m_baud);
    m_parity = new QComboBox(this);
    m_parity->addItem(tr("None"), int(QSerialPort::NoParity));
    m_parity->addItem(tr("Even"), int(QSerialPort::EvenParity));
    m_parity->addItem(tr("Odd"), int(QSerialPort::OddParity));
    form->addRow(tr("P&arity:"), m_parity);
    m_poll = new QDoubleSpinBox(this);
    m_poll->setRange(0.5, 200);
    m_poll->setValue(10);
    m_poll->setSuffix(tr(" Hz"));
    m_poll->setToolTip(tr("How often the sensor registers are read; limited to what the baud rate carries"));
    form->addRow(tr("P&olling rate:"), m_poll);
    m_ship = new QCheckBox(tr("Also read the ship-motion registers (heave)"), this);
    form->addRow(QString(), m_ship);
    auto *layout = new QVBoxLayout(this);
    layout->addLayout(form);
    addButtons(this, layout);
    connect(m_kind, &QComboBox::currentIndexChanged, this, &ModbusConnectDialog::updateDefaults);
    connect(m_port, &QComboBox::currentIndexChanged, this, [this] {
        const QString key = m_port->currentData().toString();
        if (key.startsWith(QLatin1String(kSimulatedKey)))
            m_kind->setCurrentIndex(key.endsWith(QLatin1String("hec495")) ? 1 : 0);
    });
    m_port->setCurrentIndex(m_port->count() - 2); // the simulated HiPNUC when there is no adapter
    if (QSerialPortInfo::availablePorts().size() > 0)
        m_port->setCurrentIndex(0);
    updateDefaults();
}

void ModbusConnectDialog::updateDefaults()
{
    const bool hec = DeviceKind(m_kind->currentData().toInt()) == DeviceKind::Hec495;
    m_node->setValue(hec ? 1 : 80);
    m_baud->setCurrentIndex(m_baud->findData(hec ? 9600 : 115200));
    m_ship->setEnabled(!hec);
}

bool ModbusConnectDialog::simulate() const
{
    return m_port->currentData().toString().startsWith(QLatin1String(kSimulatedKey));
}

device::ModbusOptions ModbusConnectDialog::options() const
{
    device::ModbusOptions o;
    o.port = simulate() ? QString() : m_port->currentData().toString();
    o.kind = DeviceKind(m_kind->currentData().toInt());
    o.nodeId = m_node->value();
    o.baud = m_baud->currentData().toInt();
    o.parity = QSerialPort::Parity(m_parity->currentData().toInt());
    o.pollHz = m_poll->value();
    o.shipMotion = m_ship->isEnabled() && m_ship->isChecked();
    return o;
}

// ---------------------------------------------------------------- CAN

CanConnectDialog::CanConnectDialog(QWidget *parent) : QDialog(parent)
{
    setWindowTitle(tr("Connect over CAN"));
    setObjectName(QStringLiteral("canConnectDialog"));
    auto *form = new QFormLayout;
    m_plugin = new QComboBox(this);
    m_plugin->addItems(device::CanSession::plugins());
    m_plugin->setToolTip(tr("The Qt CAN plugin of the adapter: socketcan for Linux CAN interfaces, peakcan for PEAK "
                            "adapters, virtualcan for a bus inside this computer"));
    form->addRow(tr("P&lugin:"), m_plugin);
    m_interface = new QComboBox(this);
    m_interface->setEditable(true);
    m_interface->setToolTip(tr("The interface of the plugin, e.g. can0"));
    form->addRow(tr("&Interface:"), m_interface);
    m_bitrate = new QComboBox(this);
    m_bitrate->setObjectName(QStringLiteral("canBitrate"));
    m_bitrate->setToolTip(tr("Bit rate of the bus: the rates the chosen device's manual lists, its factory rate "
                             "chosen first (HiPNUC 500 kbit/s, HEC495 250 kbit/s)"));
    form->addRow(tr("&Bit rate:"), m_bitrate);
    m_rateHint = new QLabel(this);
    m_rateHint->setObjectName(QStringLiteral("canRateHint"));
    m_rateHint->setWordWrap(true);
    form->addRow(QString(), m_rateHint);
    // CAN FD (v1.7.1 7.19.30): the arbitration phase at the bit rate above, the data phase
    // faster ("usually 4 Mbps"); the J1939 FF5A frame of 64 bytes comes only on such a bus.
    m_fd = new QCheckBox(tr("CAN FD"), this);
    m_fd->setObjectName(QStringLiteral("canFd"));
    m_fd->setToolTip(tr("A CAN FD bus: needed for the J1939 FF5A frame (64 bytes); the module must have CAN FD "
                        "output enabled, which its manual gives no command for"));
    m_dataBitrate = new QComboBox(this);
    m_dataBitrate->setObjectName(QStringLiteral("canDataBitrate"));
    for (int b : {1000000, 2000000, 4000000, 5000000, 8000000})
        m_dataBitrate->addItem(tr("%1 Mbit/s").arg(b / 1000000), b);
    m_dataBitrate->setCurrentIndex(m_dataBitrate->findData(4000000));
    m_dataBitrate->setToolTip(tr("Bit rate of the CAN FD data phase (the manual: usually 4 Mbit/s)"));
    auto *fdRow = new QWidget(this);
    auto *fdLayout = new QHBoxLayout(fdRow);
    fdLayout->setContentsMargins(0, 0, 0, 0);
    fdLayout->addWidget(m_fd);
    fdLayout->addWidget(m_dataBitrate, 1);
    form->addRow(tr("&Data phase:"), fdRow);
    connect(m_fd, &QCheckBox::toggled, m_dataBitrate, &QWidget::setEnabled);
    m_dataBitrate->setEnabled(false);
    m_protocol = new QComboBox(this);
    m_protocol->addItem(tr("Detect from the traffic"), int(protocol::can::CanProtocol::Auto));
    m_protocol->addItem(QStringLiteral("J1939"), int(protocol::can::CanProtocol::J1939));
    m_protocol->addItem(QStringLiteral("CANopen"), int(protocol::can::CanProtocol::CanOpen));
    m_protocol->addItem(tr("HEC495 compass"), int(protocol::can::CanProtocol::Hec495));
    form->addRow(tr("P&rotocol:"), m_protocol);
    m_hecExtended = new QCheckBox(tr("Extended frames (0x18FA…)"), this);
    m_hecExtended->setToolTip(tr("The HEC495's extended-frame variant: requests on 0x18FA0227, replies on 0x18FA0216, "
                                 "data on 0x18FA0316 and 0x18FA0416 (its manual, \"CAN 扩展帧命令格式\")"));
    form->addRow(QString(), m_hecExtended);
    m_node = new QSpinBox(this);
    m_node->setRange(-1, 253);
    m_node->setSpecialValueText(tr("First that sends"));
    m_node->setValue(-1);
    m_node->setToolTip(tr("The node ID (CANopen) or source address (J1939) to follow"));
    form->addRow(tr("&Node:"), m_node);
    m_firmware = new QComboBox(this);
    m_firmware->addItem(tr("1.7.x (node-ID object 0x209C)"), 0x209C);
    m_firmware->addItem(tr("1.6.6 (node-ID object 0x20A0)"), 0x20A0);
    m_firmware->setToolTip(tr("HiPNUC CANopen firmware: where it keeps its node ID"));
    form->addRow(tr("&Firmware:"), m_firmware);
    m_simulate = new QCheckBox(tr("Start a simulated device on this bus"), this);
    m_simulate->setToolTip(tr("A simulated module of the chosen protocol answers on the bus (use the virtualcan "
                              "plugin to try it without hardware)"));
    form->addRow(QString(), m_simulate);
    auto *layout = new QVBoxLayout(this);
    layout->addLayout(form);
    addButtons(this, layout);
    connect(m_plugin, &QComboBox::currentIndexChanged, this, &CanConnectDialog::refreshInterfaces);
    auto hecOnly = [this] {
        m_hecExtended->setEnabled(m_protocol->currentData().toInt() == int(protocol::can::CanProtocol::Hec495));
    };
    connect(m_protocol, &QComboBox::currentIndexChanged, this, hecOnly);
    connect(m_protocol, &QComboBox::currentIndexChanged, this, &CanConnectDialog::refreshRates);
    connect(m_hecExtended, &QCheckBox::toggled, this, &CanConnectDialog::refreshRates);
    hecOnly();
    refreshRates();
    const int virt = m_plugin->findText(QStringLiteral("virtualcan"));
    if (virt >= 0) {
        m_plugin->setCurrentIndex(virt);
        m_simulate->setChecked(true);
        m_protocol->setCurrentIndex(1);
    }
    refreshInterfaces();
}

void CanConnectDialog::refreshRates()
{
    const auto protocol = protocol::can::CanProtocol(m_protocol->currentData().toInt());
    const bool extended = protocol == protocol::can::CanProtocol::Hec495 && m_hecExtended->isChecked();
    const protocol::can::CanBitrates rates = protocol::can::canBitrates(protocol, extended);
    const int chosen = m_bitrate->currentData().toInt();
    const bool keepChoice = m_bitrate->count() > 0 && m_protocolShown == int(protocol);
    m_bitrate->clear();
    m_bitrate->addItem(tr("Keep the interface's setting"), 0);
    for (int r : rates.rates)
        m_bitrate->addItem(r == rates.factory && protocol != protocol::can::CanProtocol::Auto
                               ? tr("%1 kbit/s (factory)").arg(r / 1000)
                               : tr("%1 kbit/s").arg(r / 1000),
                           r);
    const int index = m_bitrate->findData(keepChoice ? chosen : rates.factory);
    m_bitrate->setCurrentIndex(index >= 0 ? index : m_bitrate->findData(rates.factory));
    m_protocolShown = int(protocol);
    // What the module itself can be switched to (its own bit-rate setting).
    QStringList own;
    for (int r : device::CanSession::moduleBitrates(protocol, extended))
        own << QString::number(r / 1000);
    switch (protocol) {
    case protocol::can::CanProtocol::J1939:
        m_rateHint->setText(tr("The module can be switched to %1 kbit/s (register 0x9A, after save and reset).")
                                .arg(own.join(QStringLiteral(", "))));
        break;
    case protocol::can::CanProtocol::CanOpen:
        m_rateHint->setText(tr("The module can be switched to %1 kbit/s (object 0x209A, after save and reset; no "
                               "800 kbit/s in CANopen).")
                                .arg(own.join(QStringLiteral(", "))));
        break;
    case protocol::can::CanProtocol::Hec495:
        m_rateHint->setText(tr("The compass can be switched to %1 kbit/s (object 0x1020, after a power cycle).")
                                .arg(own.join(QStringLiteral(", "))));
        break;
    case protocol::can::CanProtocol::Auto:
        m_rateHint->setText(tr("Choose the protocol to see the rates its devices use."));
        break;
    }
}

void CanConnectDialog::refreshInterfaces()
{
    m_interface->clear();
    QString error;
    const QStringList names = device::CanSession::interfaces(m_plugin->currentText(), &error);
    m_interface->addItems(names.isEmpty() ? QStringList{QStringLiteral("can0")} : names);
}

bool CanConnectDialog::simulate() const
{
    return m_simulate->isChecked();
}

device::CanSessionOptions CanConnectDialog::options() const
{
    device::CanSessionOptions o;
    o.plugin = m_plugin->currentText();
    o.interfaceName = m_interface->currentText().trimmed();
    o.bitrate = m_bitrate->currentData().toInt();
    o.canFd = m_fd->isChecked();
    o.dataBitrate = o.canFd ? m_dataBitrate->currentData().toInt() : 0;
    o.protocol = protocol::can::CanProtocol(m_protocol->currentData().toInt());
    if (simulate() && o.protocol == protocol::can::CanProtocol::Auto)
        o.protocol = protocol::can::CanProtocol::J1939;
    o.node = m_node->value();
    o.hipnucNodeIdObject = uint16_t(m_firmware->currentData().toInt());
    o.hec495Extended = o.protocol == protocol::can::CanProtocol::Hec495 && m_hecExtended->isChecked();
    return o;
}

} // namespace imudesk::ui
