#include "live_bridge_dialog.h"

#include "bridge/bridge_controller.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDateTime>
#include <QEvent>
#include <QFormLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QHostAddress>
#include <QLabel>
#include <QLineEdit>
#include <QMessageBox>
#include <QPlainTextEdit>
#include <QPushButton>
#include <QSettings>
#include <QSpinBox>
#include <QVBoxLayout>

namespace imudesk::ui {

namespace {
constexpr const char *kLoopback = "127.0.0.1";
constexpr const char *kAll = "0.0.0.0";

// A port field and its label, as a form's row.
QSpinBox *portRow(QFormLayout *form, const char *name, int value, QLabel **label)
{
    auto *box = new QSpinBox(form->parentWidget());
    box->setObjectName(QLatin1String(name));
    box->setRange(1, 65535);
    box->setValue(value);
    *label = new QLabel(form->parentWidget());
    (*label)->setBuddy(box);
    form->addRow(*label, box);
    return box;
}

QHostAddress addressOf(const QComboBox *box)
{
    // The items carry the address as data; what is typed is taken as an address.
    const QString text = box->currentIndex() >= 0 && box->currentText() == box->itemText(box->currentIndex())
                             ? box->currentData().toString()
                             : box->currentText().trimmed();
    return QHostAddress(text.isEmpty() ? QString::fromLatin1(kLoopback) : text);
}
} // namespace

LiveBridgeDialog::LiveBridgeDialog(BridgeController *controller, QWidget *parent)
    : QDialog(parent), m_controller(controller)
{
    setObjectName(QStringLiteral("liveBridgeDialog"));
    auto *top = new QVBoxLayout(this);

    m_wsBox = new QGroupBox(this);
    m_wsBox->setCheckable(true);
    m_wsBox->setObjectName(QStringLiteral("websocketBox"));
    auto *wsForm = new QFormLayout(m_wsBox);
    m_address = new QComboBox(m_wsBox);
    m_address->setObjectName(QStringLiteral("bridgeAddress"));
    m_address->setEditable(true);
    m_address->addItem(QString(), QString::fromLatin1(kLoopback));
    m_address->addItem(QString(), QString::fromLatin1(kAll));
    m_addressLabel = new QLabel(m_wsBox);
    m_addressLabel->setBuddy(m_address);
    wsForm->addRow(m_addressLabel, m_address);
    const bridge::BridgeOptions defaults;
    m_port = portRow(wsForm, "bridgePort", defaults.port, &m_portLabel);
    m_warning = new QLabel(m_wsBox);
    m_warning->setObjectName(QStringLiteral("bridgeWarning"));
    m_warning->setWordWrap(true);
    m_warning->setStyleSheet(QStringLiteral("color: #b35c00;"));
    wsForm->addRow(m_warning);
    m_howTo = new QLabel(m_wsBox);
    m_howTo->setWordWrap(true);
    m_howTo->setTextInteractionFlags(Qt::TextSelectableByMouse);
    wsForm->addRow(m_howTo);
    top->addWidget(m_wsBox);

    m_udpBox = new QGroupBox(this);
    m_udpBox->setCheckable(true);
    m_udpBox->setChecked(false);
    m_udpBox->setObjectName(QStringLiteral("udpBox"));
    auto *udpForm = new QFormLayout(m_udpBox);
    m_udpHost = new QLineEdit(QString::fromLatin1(kLoopback), m_udpBox);
    m_udpHost->setObjectName(QStringLiteral("udpHost"));
    m_udpHostLabel = new QLabel(m_udpBox);
    m_udpHostLabel->setBuddy(m_udpHost);
    udpForm->addRow(m_udpHostLabel, m_udpHost);
    m_udpPort = portRow(udpForm, "udpPort", defaults.udpPort, &m_udpPortLabel);
    top->addWidget(m_udpBox);

    auto *row = new QHBoxLayout;
    m_startStop = new QPushButton(this);
    m_startStop->setObjectName(QStringLiteral("bridgeStartStop"));
    m_startStop->setDefault(true);
    row->addWidget(m_startStop);
    m_status = new QLabel(this);
    m_status->setObjectName(QStringLiteral("bridgeStatus"));
    m_status->setWordWrap(true);
    row->addWidget(m_status, 1);
    top->addLayout(row);

    m_logLabel = new QLabel(this);
    top->addWidget(m_logLabel);
    m_log = new QPlainTextEdit(this);
    m_log->setObjectName(QStringLiteral("bridgeLog"));
    m_log->setReadOnly(true);
    m_log->setMaximumBlockCount(500); // bounded, as every buffer
    m_log->setMinimumHeight(120);
    m_logLabel->setBuddy(m_log);
    top->addWidget(m_log, 1);
    auto *buttons = new QHBoxLayout;
    buttons->addStretch(1);
    m_close = new QPushButton(this);
    buttons->addWidget(m_close);
    top->addLayout(buttons);

    connect(m_close, &QPushButton::clicked, this, &QDialog::close);
    connect(m_startStop, &QPushButton::clicked, this, [this] {
        if (m_controller->bridge().isRunning())
            stopBridge();
        else if (!startBridge())
            QMessageBox::warning(this, windowTitle(), m_lastError);
    });
    connect(m_address, &QComboBox::currentTextChanged, this, &LiveBridgeDialog::updateWarning);
    connect(m_port, &QSpinBox::valueChanged, this, &LiveBridgeDialog::retranslate); // the port in the how-to
    connect(m_controller, &BridgeController::statusChanged, this, &LiveBridgeDialog::updateState);
    connect(m_controller, &BridgeController::runningChanged, this, &LiveBridgeDialog::updateState);
    connect(&m_controller->bridge(), &bridge::LiveBridge::logged, this, [this](const QString &line) {
        m_log->appendPlainText(QDateTime::currentDateTime().toString(QStringLiteral("HH:mm:ss  ")) + line);
    });
    loadSettings();
    retranslate();
    updateState();
    resize(sizeHint().expandedTo(QSize(560, 480)));
}

void LiveBridgeDialog::changeEvent(QEvent *event)
{
    if (event->type() == QEvent::LanguageChange)
        retranslate();
    QDialog::changeEvent(event);
}

void LiveBridgeDialog::retranslate()
{
    setWindowTitle(tr("Live bridge"));
    m_wsBox->setTitle(tr("Foxglove WebSocket (Foxglove, Lichtblick, PlotJuggler)"));
    m_addressLabel->setText(tr("&Address:"));
    m_address->setItemText(0, tr("127.0.0.1 (this computer only)"));
    m_address->setItemText(1, tr("0.0.0.0 (every network of this computer)"));
    m_address->setToolTip(tr("Where clients may connect from. Another address than 127.0.0.1 lets anyone on that network "
                             "read the data: the Foxglove protocol has no password."));
    m_portLabel->setText(tr("&Port:"));
    m_port->setToolTip(tr("TCP port of the WebSocket server (Foxglove's usual port: 8765)"));
    m_howTo->setText(tr("Foxglove and Lichtblick: Open connection > Foxglove WebSocket, ws://127.0.0.1:%1. PlotJuggler: "
                        "Streaming > Foxglove Bridge. Each device's topics are /imu/<serial>/imu, mag, euler, status, ... "
                        "as in an MCAP recording.").arg(m_port->value()));
    m_udpBox->setTitle(tr("PlotJuggler UDP (JSON)"));
    m_udpHostLabel->setText(tr("&Host:"));
    m_udpHost->setToolTip(tr("Computer running PlotJuggler's UDP server (Streaming > UDP Server, message protocol JSON, "
                             "time stamp from the field \"timestamp\")"));
    m_udpPortLabel->setText(tr("P&ort:"));
    m_udpPort->setToolTip(tr("UDP port PlotJuggler listens on (its default: 9870)"));
    m_logLabel->setText(tr("&Log (clients, refused requests, dropped messages):"));
    m_close->setText(tr("Close"));
    updateWarning();
    updateState();
}

void LiveBridgeDialog::updateWarning()
{
    const QHostAddress a = addressOf(m_address);
    m_warning->setVisible(!a.isNull() && !a.isLoopback());
    m_warning->setText(a.isNull() ? QString()
                                  : tr("Warning: %1 is not this computer only. Anyone who can reach it on the network can "
                                       "read the devices' data: the protocol has no password.").arg(a.toString()));
}

void LiveBridgeDialog::updateState()
{
    const bool running = m_controller->bridge().isRunning();
    m_startStop->setText(running ? tr("&Stop") : tr("&Start"));
    m_startStop->setToolTip(running ? tr("Stop the bridge (Ctrl+Shift+B opens this window)")
                                    : tr("Send the connected devices' samples from now on"));
    m_wsBox->setEnabled(!running);
    m_udpBox->setEnabled(!running);
    if (!running) {
        m_status->setText(tr("Stopped"));
        return;
    }
    const bridge::BridgeStats s = m_controller->bridge().stats();
    m_status->setText(tr("%1\n%2 device(s); samples: %3, missed: %4").arg(m_controller->statusText())
                          .arg(s.devices).arg(s.samples).arg(s.samplesMissed));
}

bool LiveBridgeDialog::startBridge()
{
    bridge::BridgeOptions o;
    o.websocket = m_wsBox->isChecked();
    o.address = addressOf(m_address);
    o.port = quint16(m_port->value());
    o.udp = m_udpBox->isChecked();
    o.udpHost = QHostAddress(m_udpHost->text().trimmed() == QLatin1String("localhost") ? QString::fromLatin1(kLoopback)
                                                                                         : m_udpHost->text().trimmed());
    o.udpPort = quint16(m_udpPort->value());
    if (!o.websocket && !o.udp) {
        m_lastError = tr("Choose the Foxglove WebSocket server, PlotJuggler UDP or both.");
        return false;
    }
    if (o.websocket && o.address.isNull()) {
        m_lastError = tr("'%1' is not an IP address. Use 127.0.0.1 for this computer only or 0.0.0.0 for every network.")
                          .arg(m_address->currentText());
        return false;
    }
    if (o.udp && o.udpHost.isNull()) {
        m_lastError = tr("'%1' is not an IP address: give the address of the computer running PlotJuggler, e.g. 127.0.0.1.")
                          .arg(m_udpHost->text());
        return false;
    }
    QString error;
    if (!m_controller->start(o, &error)) {
        m_lastError = tr("%1\nChoose another port, or close the program that uses this one.").arg(error);
        return false;
    }
    m_lastError.clear();
    saveSettings();
    retranslate();
    return true;
}

void LiveBridgeDialog::stopBridge()
{
    m_controller->stop();
}

void LiveBridgeDialog::loadSettings()
{
    QSettings s;
    s.beginGroup(QStringLiteral("bridge"));
    m_wsBox->setChecked(s.value(QStringLiteral("websocket"), true).toBool());
    const QString address = s.value(QStringLiteral("address"), QString::fromLatin1(kLoopback)).toString();
    const int item = m_address->findData(address);
    if (item >= 0)
        m_address->setCurrentIndex(item);
    else
        m_address->setEditText(address);
    const bridge::BridgeOptions defaults;
    m_port->setValue(s.value(QStringLiteral("port"), defaults.port).toInt());
    m_udpBox->setChecked(s.value(QStringLiteral("udp"), false).toBool());
    m_udpHost->setText(s.value(QStringLiteral("udp_host"), QString::fromLatin1(kLoopback)).toString());
    m_udpPort->setValue(s.value(QStringLiteral("udp_port"), defaults.udpPort).toInt());
}

void LiveBridgeDialog::saveSettings() const
{
    QSettings s;
    s.beginGroup(QStringLiteral("bridge"));
    s.setValue(QStringLiteral("websocket"), m_wsBox->isChecked());
    s.setValue(QStringLiteral("address"), addressOf(m_address).toString());
    s.setValue(QStringLiteral("port"), m_port->value());
    s.setValue(QStringLiteral("udp"), m_udpBox->isChecked());
    s.setValue(QStringLiteral("udp_host"), m_udpHost->text());
    s.setValue(QStringLiteral("udp_port"), m_udpPort->value());
}

} // namespace imudesk::ui
