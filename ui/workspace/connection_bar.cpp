#include "workspace/connection_bar.h"

#include "links/serial_family.h"

#include <QAbstractItemView>
#include <QComboBox>
#include <QEvent>
#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QSerialPortInfo>
#include <QStandardItemModel>
#include <QStyle>
#include <QToolButton>

#include <algorithm>

namespace imudesk::ui {

namespace {

constexpr int kKeyRole = Qt::UserRole;

bool isBusy(device::SessionState s)
{
    return s == device::SessionState::Opening || s == device::SessionState::Detecting
        || s == device::SessionState::Connected;
}

} // namespace

ConnectionBar::ConnectionBar(QWidget *parent) : QWidget(parent)
{
    m_portLabel = new QLabel(this);
    m_portCombo = new QComboBox(this);
    m_portCombo->setObjectName(QStringLiteral("portCombo"));
    m_portCombo->setSizeAdjustPolicy(QComboBox::AdjustToContents);
    m_portCombo->setMinimumContentsLength(28);
    m_portLabel->setBuddy(m_portCombo);
    m_targetLabel = new QLabel(this);
    m_targetLabel->setObjectName(QStringLiteral("connectedTarget"));
    m_targetLabel->setFrameShape(QFrame::StyledPanel);
    m_targetLabel->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_targetLabel->setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Preferred);
    m_targetLabel->hide();

    m_refreshButton = new QToolButton(this);
    m_refreshButton->setObjectName(QStringLiteral("refreshPortsButton"));
    m_refreshButton->setIcon(style()->standardIcon(QStyle::SP_BrowserReload));
    m_refreshButton->setToolButtonStyle(Qt::ToolButtonTextBesideIcon);

    m_baudLabel = new QLabel(this);
    m_baudCombo = new QComboBox(this);
    m_baudCombo->setObjectName(QStringLiteral("baudCombo"));
    m_baudLabel->setBuddy(m_baudCombo);
    m_baudCombo->addItem(QString(), 0);
    std::vector<int> rates = device::serialDetectionBauds();
    std::sort(rates.begin(), rates.end());
    for (int rate : rates)
        m_baudCombo->addItem(QString::number(rate), rate);

    m_connectButton = new QPushButton(this);
    m_connectButton->setObjectName(QStringLiteral("connectButton"));
    m_connectButton->setDefault(true);

    m_findButton = new QToolButton(this);
    m_findButton->setObjectName(QStringLiteral("findDevicesButton"));
    m_findButton->setIcon(style()->standardIcon(QStyle::SP_FileDialogContentsView));
    m_findButton->setToolButtonStyle(Qt::ToolButtonTextBesideIcon);

    auto *layout = new QHBoxLayout(this);
    layout->setContentsMargins(6, 4, 6, 4);
    layout->addWidget(m_findButton);
    layout->addSpacing(6);
    layout->addWidget(m_portLabel);
    layout->addWidget(m_portCombo, 1);
    layout->addWidget(m_targetLabel, 1);
    layout->addWidget(m_refreshButton);
    layout->addSpacing(12);
    layout->addWidget(m_baudLabel);
    layout->addWidget(m_baudCombo);
    layout->addSpacing(12);
    layout->addWidget(m_connectButton);

    connect(m_refreshButton, &QToolButton::clicked, this, &ConnectionBar::refreshPorts);
    connect(m_findButton, &QToolButton::clicked, this, &ConnectionBar::findDevicesRequested);
    connect(m_connectButton, &QPushButton::clicked, this, &ConnectionBar::onButtonClicked);
    m_scanTimer.setInterval(kPortScanIntervalMs);
    connect(&m_scanTimer, &QTimer::timeout, this, &ConnectionBar::refreshPorts);

    retranslateUi();
    refreshPorts();
    rebuildPortCombo();
}

PortChoice ConnectionBar::selectedPort() const
{
    return PortChoice::fromKey(m_portCombo->currentData(kKeyRole).toString());
}

void ConnectionBar::selectPort(const PortChoice &choice)
{
    if (!choice.isValid())
        return;
    int index = m_portCombo->findData(choice.key(), kKeyRole);
    if (index < 0) {
        m_extraPorts.push_back(choice);
        rebuildPortCombo();
        index = m_portCombo->findData(choice.key(), kKeyRole);
    }
    if (index >= 0)
        m_portCombo->setCurrentIndex(index);
}

int ConnectionBar::selectedBaud() const
{
    return m_baudCombo->currentData().toInt();
}

void ConnectionBar::selectBaud(int baud)
{
    const int index = m_baudCombo->findData(baud);
    m_baudCombo->setCurrentIndex(index >= 0 ? index : 0);
}

void ConnectionBar::setSessionState(device::SessionState state)
{
    m_state = state;
    const bool busy = isBusy(state);
    m_portCombo->setEnabled(!busy);
    m_baudCombo->setEnabled(!busy);
    retranslateUi();
    updateTargetLabel();
    updateScanning();
}

void ConnectionBar::updateScanning()
{
    // The list is watched while a port can be chosen: not while a device is connected (the
    // list is hidden then, and one scan reads a few thousand sysfs entries).
    const bool wanted = isVisible() && !isBusy(m_state);
    if (wanted && !m_scanTimer.isActive()) {
        refreshPorts();
        m_scanTimer.start();
    } else if (!wanted) {
        m_scanTimer.stop();
    }
}

void ConnectionBar::setConnectedTarget(const QString &target)
{
    m_target = target;
    updateTargetLabel();
}

void ConnectionBar::updateTargetLabel()
{
    const bool show = isBusy(m_state) && !m_target.isEmpty();
    m_targetLabel->setText(m_target);
    m_targetLabel->setToolTip(m_target);
    m_targetLabel->setVisible(show);
    m_portCombo->setVisible(!show);
    m_portLabel->setBuddy(show ? static_cast<QWidget *>(m_targetLabel) : m_portCombo);
}

QString ConnectionBar::shownTarget() const
{
    return !m_targetLabel->isHidden() ? m_targetLabel->text() : m_portCombo->currentText();
}

QStringList ConnectionBar::portTexts() const
{
    QStringList out;
    for (int i = 0; i < m_portCombo->count(); ++i)
        if (!m_portCombo->itemData(i, kKeyRole).toString().isEmpty())
            out << m_portCombo->itemText(i);
    return out;
}

void ConnectionBar::refreshPorts()
{
    std::vector<PortEntry> found;
    for (const QSerialPortInfo &info : QSerialPortInfo::availablePorts()) {
        PortEntry e;
        e.choice = PortChoice::serial(info.systemLocation());
        QStringList parts;
        if (!info.description().isEmpty())
            parts << info.description();
        if (!info.serialNumber().isEmpty())
            parts << tr("SN %1").arg(info.serialNumber());
        e.description = parts.join(QStringLiteral(", "));
        QStringList tip{info.systemLocation()};
        if (!info.manufacturer().isEmpty())
            tip << tr("Manufacturer: %1").arg(info.manufacturer());
        if (info.hasVendorIdentifier() && info.hasProductIdentifier())
            tip << tr("USB ID: %1:%2")
                       .arg(info.vendorIdentifier(), 4, 16, QLatin1Char('0'))
                       .arg(info.productIdentifier(), 4, 16, QLatin1Char('0'));
        e.toolTip = tip.join(QLatin1Char('\n'));
        found.push_back(std::move(e));
    }
    std::sort(found.begin(), found.end(),
              [](const PortEntry &a, const PortEntry &b) { return a.choice.port < b.choice.port; });
    if (found == m_serialPorts)
        return;
    // Never rebuild under an open popup; the next scan catches up.
    if (m_portCombo->view() && m_portCombo->view()->isVisible())
        return;
    m_serialPorts = std::move(found);
    rebuildPortCombo();
}

void ConnectionBar::changeEvent(QEvent *event)
{
    if (event->type() == QEvent::LanguageChange) {
        retranslateUi();
        rebuildPortCombo();
    }
    QWidget::changeEvent(event);
}

void ConnectionBar::showEvent(QShowEvent *event)
{
    QWidget::showEvent(event);
    updateScanning();
}

void ConnectionBar::hideEvent(QHideEvent *event)
{
    m_scanTimer.stop();
    QWidget::hideEvent(event);
}

void ConnectionBar::retranslateUi()
{
    m_portLabel->setText(tr("&Port:"));
    m_portCombo->setToolTip(tr("Serial port of the IMU, or a simulated device that runs inside ImuDesk"));
    m_findButton->setText(tr("Find devices…"));
    m_findButton->setToolTip(tr("Sweep every serial port and CAN bus for devices (Ctrl+Shift+F)"));
    m_refreshButton->setText(tr("Refresh"));
    m_refreshButton->setToolTip(tr("Scan for serial ports again (the list also refreshes every 2 s)"));
    m_baudLabel->setText(tr("&Baud rate:"));
    m_baudCombo->setItemText(0, tr("Auto"));
    m_baudCombo->setToolTip(tr("Auto finds the device and the baud rate it talks at, starting with 115200"));
    if (isBusy(m_state)) {
        m_connectButton->setText(tr("Disconnect"));
        m_connectButton->setToolTip(tr("Close the connection (Ctrl+D)"));
    } else {
        m_connectButton->setText(tr("Connect"));
        m_connectButton->setToolTip(tr("Connect to the selected port (Ctrl+K)"));
    }
}

QString ConnectionBar::portText(const PortChoice &choice) const
{
    switch (choice.kind) {
    case PortChoice::Kind::Simulated:
        for (const auto &d : m_simulated)
            if (d.choice == choice)
                return d.text;
        if (choice.firmware.isEmpty())
            return tr("Simulated %1").arg(choice.model);
        return tr("Simulated %1 (firmware %2)").arg(choice.model, choice.firmware);
    case PortChoice::Kind::Serial: {
        for (const auto &e : m_serialPorts)
            if (e.choice == choice)
                return e.description.isEmpty() ? choice.port : tr("%1 (%2)").arg(choice.port, e.description);
        return choice.port;
    }
    case PortChoice::Kind::None: break;
    }
    return QString();
}

void ConnectionBar::setSimulatedDevices(std::function<std::vector<SimulatedDevice>()> devices)
{
    m_simulatedDevices = std::move(devices);
    rebuildPortCombo();
}

void ConnectionBar::rebuildPortCombo()
{
    const QString current = m_portCombo->currentData(kKeyRole).toString();
    // Asked each time: their texts follow the language.
    m_simulated = m_simulatedDevices ? m_simulatedDevices() : std::vector<SimulatedDevice>{};
    const QSignalBlocker blocker(m_portCombo);
    m_portCombo->clear();
    auto add = [this](const PortChoice &choice, const QString &toolTip) {
        if (m_portCombo->findData(choice.key(), kKeyRole) >= 0)
            return;
        m_portCombo->addItem(portText(choice), choice.key());
        m_portCombo->setItemData(m_portCombo->count() - 1, toolTip, Qt::ToolTipRole);
    };
    for (const auto &e : m_serialPorts)
        add(e.choice, e.toolTip);
    for (const auto &c : m_extraPorts)
        if (c.kind == PortChoice::Kind::Serial)
            add(c, c.port);
    if (m_portCombo->count() == 0) {
        m_portCombo->addItem(tr("No serial port found"));
        if (auto *items = qobject_cast<QStandardItemModel *>(m_portCombo->model()))
            items->item(0)->setEnabled(false);
    }
    m_portCombo->insertSeparator(m_portCombo->count());
    const QString simTip = tr("A simulated device on a pseudo-terminal, driven exactly like hardware");
    for (const auto &d : m_simulated)
        add(d.choice, simTip);
    for (const auto &c : m_extraPorts)
        if (c.kind == PortChoice::Kind::Simulated)
            add(c, simTip);
    int index = current.isEmpty() ? -1 : m_portCombo->findData(current, kKeyRole);
    if (index < 0) // first real entry
        for (int i = 0; i < m_portCombo->count() && index < 0; ++i)
            if (!m_portCombo->itemData(i, kKeyRole).toString().isEmpty())
                index = i;
    m_portCombo->setCurrentIndex(index);
}

void ConnectionBar::onButtonClicked()
{
    if (isBusy(m_state))
        Q_EMIT disconnectRequested();
    else
        Q_EMIT connectRequested();
}

} // namespace imudesk::ui
