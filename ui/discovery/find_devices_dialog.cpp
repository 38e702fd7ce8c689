#include "ui/discovery/find_devices_dialog.h"

#include "core/discovery/found_link.h"
#include "core/discovery/simulated_bench.h"
#include "io/can_transport.h"

#include <QCheckBox>
#include <QEvent>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QListWidget>
#include <QProgressBar>
#include <QPushButton>
#include <QSettings>
#include <QSpinBox>
#include <QTableWidget>
#include <QVBoxLayout>

namespace imudesk::ui {

using discovery::FoundDevice;

namespace {

const char *kGroup = "findDevices";

QStringList splitList(const QString &text)
{
    QStringList out;
    for (const QString &part : text.split(QLatin1Char(','), Qt::SkipEmptyParts))
        if (!part.trimmed().isEmpty())
            out << part.trimmed();
    return out;
}

} // namespace

FindDevicesDialog::FindDevicesDialog(ConnectFn connect, QWidget *parent) : QDialog(parent), m_connect(std::move(connect))
{
    setObjectName(QStringLiteral("findDevicesDialog"));
    auto *layout = new QVBoxLayout(this);
    m_intro = new QLabel(this);
    m_intro->setWordWrap(true);
    layout->addWidget(m_intro);

    auto *form = new QFormLayout;
    m_ports = new QLineEdit(this);
    m_ports->setObjectName(QStringLiteral("extraPorts"));
    m_ports->setClearButtonEnabled(true);
    m_portsLabel = new QLabel(this);
    m_portsLabel->setBuddy(m_ports);
    form->addRow(m_portsLabel, m_ports);
    m_buses = new QLineEdit(this);
    m_buses->setObjectName(QStringLiteral("canBuses"));
    m_buses->setClearButtonEnabled(true);
    m_busesLabel = new QLabel(this);
    m_busesLabel->setBuddy(m_buses);
    form->addRow(m_busesLabel, m_buses);
    auto *options = new QHBoxLayout;
    m_onlyListed = new QCheckBox(this);
    m_onlyListed->setObjectName(QStringLiteral("onlyListed"));
    options->addWidget(m_onlyListed);
    m_modbus = new QCheckBox(this);
    m_modbus->setChecked(true);
    options->addWidget(m_modbus);
    m_timeLabel = new QLabel(this);
    options->addWidget(m_timeLabel);
    m_time = new QSpinBox(this);
    m_time->setRange(5, 600);
    m_time->setValue(60);
    m_timeLabel->setBuddy(m_time);
    options->addWidget(m_time);
    m_simulated = new QCheckBox(this);
    m_simulated->setObjectName(QStringLiteral("simulatedBench"));
    options->addWidget(m_simulated);
    options->addStretch(1);
    form->addRow(options);
    layout->addLayout(form);

    auto *run = new QHBoxLayout;
    m_start = new QPushButton(this);
    m_start->setDefault(true);
    m_cancel = new QPushButton(this);
    m_cancel->setEnabled(false);
    m_progress = new QProgressBar(this);
    m_progress->setRange(0, 1000);
    m_progress->setValue(0);
    m_progress->setTextVisible(true);
    m_progress->setFormat(QStringLiteral("%p %"));
    run->addWidget(m_start);
    run->addWidget(m_cancel);
    run->addWidget(m_progress, 1);
    layout->addLayout(run);
    m_status = new QLabel(this);
    m_status->setObjectName(QStringLiteral("sweepStatus"));
    m_status->setWordWrap(true);
    layout->addWidget(m_status);

    m_table = new QTableWidget(0, ColCount, this);
    m_table->setObjectName(QStringLiteral("foundDevices"));
    m_table->setSelectionBehavior(QAbstractItemView::SelectRows);
    m_table->setEditTriggers(QAbstractItemView::NoEditTriggers);
    m_table->verticalHeader()->hide();
    m_table->horizontalHeader()->setStretchLastSection(false);
    m_table->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    m_table->horizontalHeader()->setSectionResizeMode(ColPort, QHeaderView::Stretch);
    layout->addWidget(m_table, 3);
    m_findingsLabel = new QLabel(this);
    layout->addWidget(m_findingsLabel);
    m_findings = new QListWidget(this);
    m_findings->setObjectName(QStringLiteral("sweepFindings"));
    m_findings->setWordWrap(true);
    m_findings->setAlternatingRowColors(true);
    layout->addWidget(m_findings, 2);

    auto *buttons = new QHBoxLayout;
    m_connectAll = new QPushButton(this);
    m_connectAll->setEnabled(false);
    m_close = new QPushButton(this);
    buttons->addWidget(m_connectAll);
    buttons->addStretch(1);
    buttons->addWidget(m_close);
    layout->addLayout(buttons);

    QObject::connect(m_start, &QPushButton::clicked, this, &FindDevicesDialog::start);
    QObject::connect(m_cancel, &QPushButton::clicked, this, &FindDevicesDialog::cancel);
    QObject::connect(m_close, &QPushButton::clicked, this, &QDialog::reject);
    QObject::connect(m_connectAll, &QPushButton::clicked, this, [this] {
        int opened = 0;
        for (int row = 0; row < m_table->rowCount(); ++row) {
            auto *b = qobject_cast<QPushButton *>(m_table->cellWidget(row, ColConnect));
            if (b && !b->isEnabled())
                continue; // opened already
            if (!connectRow(row))
                return; // the status says why
            ++opened;
        }
        m_connectAll->setEnabled(false);
        m_status->setText(tr("%n device(s) opened, each in a tab of its own.", nullptr, opened));
    });
    QObject::connect(m_table, &QTableWidget::cellDoubleClicked, this, [this](int row, int) { connectRow(row); });
    QObject::connect(m_simulated, &QCheckBox::toggled, this, [this](bool on) {
        if (!useSimulatedBench(on))
            m_simulated->setChecked(false);
    });
    QObject::connect(&m_sweep, &discovery::BenchSweep::progress, this, &FindDevicesDialog::onProgress);
    QObject::connect(&m_sweep, &discovery::BenchSweep::deviceFound, this, &FindDevicesDialog::addDevice);
    QObject::connect(&m_sweep, &discovery::BenchSweep::finished, this, &FindDevicesDialog::onFinished);

    retranslateUi();
    loadSettings();
    resize(1100, 640);
}

FindDevicesDialog::~FindDevicesDialog()
{
    m_sweep.disconnect(this);
    m_sweep.cancel();
}

void FindDevicesDialog::retranslateUi()
{
    setWindowTitle(tr("Find devices"));
    m_intro->setText(tr("One sweep of every serial port and CAN bus: each serial family at its rates, silent ports as "
                        "Modbus RTU lines, CAN buses listened to before anything is sent. Nothing is written to a "
                        "device and every port is closed afterwards."));
    m_portsLabel->setText(tr("More &serial ports:"));
    m_ports->setPlaceholderText(tr("beside the machine's, comma-separated, e.g. /dev/pts/3,/dev/ttyUSB4"));
    m_ports->setToolTip(tr("Ports the machine does not list, such as pseudo-terminals"));
    m_busesLabel->setText(tr("&CAN buses:"));
    m_buses->setPlaceholderText(tr("PLUGIN:INTERFACE, comma-separated, e.g. socketcan:can1,virtualcan:can0"));
    m_buses->setToolTip(tr("Every socketcan interface is swept anyway; name the others here"));
    m_onlyListed->setText(tr("&Only these"));
    m_onlyListed->setToolTip(tr("Sweep only the ports and buses named above, not every serial port and socketcan "
                                "interface of the machine"));
    m_modbus->setText(tr("Ask silent ports as &Modbus lines"));
    m_modbus->setToolTip(tr("Ids 80 and 1 at every rate first, then ids 1-247 at each rate, fastest first, until a "
                            "device answers or the time is up"));
    m_timeLabel->setText(tr("&Time limit:"));
    m_time->setSuffix(tr(" s"));
    m_time->setToolTip(tr("The whole sweep at most, in seconds"));
    m_simulated->setText(tr("Simulated &bench"));
    m_simulated->setToolTip(tr("Start simulated devices to find: a HiPNUC module at 460800 baud, an HEC495 at 4800 "
                               "baud address 7, a Modbus module at 38400 baud id 17, a silent port, and on virtualcan "
                               "can1 a J1939 module and two CANopen modules sharing node 5"));
    m_start->setText(tr("&Sweep"));
    m_start->setToolTip(tr("Start the sweep (F5)"));
    m_start->setShortcut(QKeySequence(Qt::Key_F5));
    m_cancel->setText(tr("Cancel"));
    m_connectAll->setText(tr("Connect &all"));
    m_connectAll->setToolTip(tr("Open every device found in a tab of its own"));
    m_close->setText(tr("Close"));
    m_findingsLabel->setText(tr("Conflicts and ports where nothing was found:"));
    m_table->setHorizontalHeaderLabels({tr("Link"), tr("Port"), tr("Rate"), tr("Family"), tr("Model"),
                                        tr("Serial number"), tr("Address / node"), tr("Firmware"), QString()});
    m_table->horizontalHeaderItem(ColRate)->setToolTip(tr("Serial: baud; CAN: bit/s"));
    for (int row = 0; row < m_table->rowCount(); ++row)
        if (auto *b = qobject_cast<QPushButton *>(m_table->cellWidget(row, ColConnect)))
            b->setText(tr("Connect"));
    if (!m_sweep.running() && m_status->text().isEmpty())
        m_status->setText(tr("Press Sweep to look at every port and bus."));
}

void FindDevicesDialog::changeEvent(QEvent *event)
{
    if (event->type() == QEvent::LanguageChange)
        retranslateUi();
    QDialog::changeEvent(event);
}

void FindDevicesDialog::done(int result)
{
    m_sweep.cancel();
    saveSettings();
    QDialog::done(result);
}

void FindDevicesDialog::loadSettings()
{
    QSettings s;
    s.beginGroup(QLatin1String(kGroup));
    m_ports->setText(s.value(QStringLiteral("ports")).toString());
    m_buses->setText(s.value(QStringLiteral("canBuses")).toString());
    m_modbus->setChecked(s.value(QStringLiteral("modbus"), true).toBool());
    m_onlyListed->setChecked(s.value(QStringLiteral("onlyListed"), false).toBool());
    m_time->setValue(s.value(QStringLiteral("seconds"), 60).toInt());
}

void FindDevicesDialog::saveSettings() const
{
    QSettings s;
    s.beginGroup(QLatin1String(kGroup));
    // The simulated bench's ports are this run's only.
    QStringList ports, buses;
    listedWithoutBench(&ports, &buses);
    s.setValue(QStringLiteral("ports"), ports.join(QLatin1Char(',')));
    s.setValue(QStringLiteral("canBuses"), buses.join(QLatin1Char(',')));
    s.setValue(QStringLiteral("modbus"), m_modbus->isChecked());
    s.setValue(QStringLiteral("onlyListed"), m_onlyListed->isChecked());
    s.setValue(QStringLiteral("seconds"), m_time->value());
}

void FindDevicesDialog::listedWithoutBench(QStringList *ports, QStringList *buses) const
{
    *ports = splitList(m_ports->text());
    *buses = splitList(m_buses->text());
    if (!m_bench)
        return;
    for (const QString &p : m_bench->ports())
        ports->removeAll(p);
    for (const QString &b : m_bench->canBuses())
        buses->removeAll(b);
}

void FindDevicesDialog::setTimeLimit(int seconds)
{
    m_time->setValue(seconds);
}

bool FindDevicesDialog::useSimulatedBench(bool on, const QString &canInterface)
{
    QStringList ports, buses;
    listedWithoutBench(&ports, &buses);
    m_bench.reset(); // a tab connected to one of its devices keeps it running
    if (on) {
        auto bench = std::make_shared<discovery::SimulatedBench>(canInterface);
        QString error;
        if (!bench->start(&error)) {
            m_status->setText(error);
            return false;
        }
        m_bench = bench;
        ports << bench->ports();
        buses << bench->canBuses();
    }
    m_ports->setText(ports.join(QLatin1Char(',')));
    m_buses->setText(buses.join(QLatin1Char(',')));
    if (m_simulated->isChecked() != on) {
        const QSignalBlocker block(m_simulated);
        m_simulated->setChecked(on);
    }
    return true;
}

discovery::SweepOptions FindDevicesDialog::options() const
{
    discovery::SweepOptions o;
    o.ports = splitList(m_ports->text());
    o.canBuses = splitList(m_buses->text());
    o.modbus = m_modbus->isChecked();
    o.machinePorts = o.machineCan = !m_onlyListed->isChecked();
    o.budgetMs = m_time->value() * 1000;
    return o;
}

void FindDevicesDialog::start()
{
    const discovery::SweepOptions o = options();
    for (const QString &bus : o.canBuses)
        if (!io::CanAddress::parse(bus).complete()) {
            m_status->setText(tr("\"%1\" is not PLUGIN:INTERFACE (e.g. socketcan:can0): correct the CAN buses field.").arg(bus));
            m_buses->setFocus();
            return;
        }
    saveSettings();
    m_found.clear();
    m_table->setRowCount(0);
    m_findings->clear();
    m_progress->setValue(0);
    const int ports = int(discovery::BenchSweep::serialPortsOf(o).size());
    const int buses = int(discovery::BenchSweep::canBusesOf(o).size());
    if (ports + buses == 0) {
        m_status->setText(tr("No serial port and no CAN bus to sweep: plug in an adapter, or name ports and buses "
                             "above (or tick Simulated bench)."));
        return;
    }
    m_status->setText(tr("Sweeping %n port(s)", nullptr, ports) + tr(" and %n CAN bus(es)…", nullptr, buses));
    setRunning(true);
    m_sweep.start(o);
}

void FindDevicesDialog::cancel()
{
    m_sweep.cancel();
}

void FindDevicesDialog::setRunning(bool on)
{
    m_start->setEnabled(!on);
    m_cancel->setEnabled(on);
    m_ports->setEnabled(!on);
    m_buses->setEnabled(!on);
    m_modbus->setEnabled(!on);
    m_onlyListed->setEnabled(!on);
    m_time->setEnabled(!on);
    m_simulated->setEnabled(!on);
    m_connectAll->setEnabled(!on && !m_found.isEmpty());
}

void FindDevicesDialog::onProgress(int done, int total, const QString &port, const QString &detail)
{
    m_progress->setMaximum(total);
    m_progress->setValue(done);
    if (!port.isEmpty() && m_sweep.running())
        m_status->setText(tr("%1: %2").arg(port, detail));
}

void FindDevicesDialog::addDevice(const FoundDevice &d)
{
    m_found.append(d);
    const int row = m_table->rowCount();
    m_table->insertRow(row);
    const auto set = [&](int col, const QString &text, const QString &tip = {}) {
        auto *item = new QTableWidgetItem(text.isEmpty() ? QStringLiteral("—") : text);
        item->setToolTip(tip.isEmpty() ? text : tip);
        m_table->setItem(row, col, item);
    };
    const QString link = d.link == FoundDevice::Link::Serial ? tr("Serial")
                         : d.link == FoundDevice::Link::Modbus ? tr("Modbus RTU")
                                                               : tr("CAN");
    set(ColLink, link);
    set(ColPort, d.port);
    if (d.link == FoundDevice::Link::Can)
        set(ColRate, d.bitrate > 0 ? tr("%1 kbit/s").arg(d.bitrate / 1000) : QString(),
            d.bitrateWhy.isEmpty() ? tr("heard without errors at this rate") : d.bitrateWhy);
    else
        set(ColRate, tr("%1 baud").arg(d.baud));
    set(ColFamily, d.family);
    set(ColModel, d.model, d.note.isEmpty() ? d.model : d.model + QStringLiteral("\n") + d.note);
    set(ColSerial, d.serial);
    set(ColAddress, d.link == FoundDevice::Link::Can ? tr("node %1").arg(d.node)
                    : d.address >= 0               ? QString::number(d.address)
                                                   : QString());
    set(ColFirmware, d.firmware);
    auto *button = new QPushButton(tr("Connect"), m_table);
    button->setToolTip(tr("Open this device in a tab of its own"));
    QObject::connect(button, &QPushButton::clicked, this, [this, row] { connectRow(row); });
    m_table->setCellWidget(row, ColConnect, button);
}

bool FindDevicesDialog::connectRow(int row)
{
    if (row < 0 || row >= m_found.size())
        return false;
    const FoundDevice &d = m_found.at(row);
    device::LinkRequest r = discovery::linkRequestFor(d);
    if (m_bench && (m_bench->ports().contains(d.port) || m_bench->canBuses().contains(d.port)))
        r.keepAlive = m_bench; // the simulated device runs as long as its tab
    QString error;
    if (!m_connect(std::move(r), &error)) {
        m_status->setText(tr("Could not connect %1: %2").arg(d.port, error));
        return false;
    }
    if (auto *b = qobject_cast<QPushButton *>(m_table->cellWidget(row, ColConnect)))
        b->setEnabled(false);
    m_status->setText(tr("%1 opened in its own tab.").arg(d.port));
    return true;
}

void FindDevicesDialog::showFindings()
{
    const discovery::SweepResult &r = m_sweep.result();
    // The rows of a conflict's address in red too, its evidence in their tooltips.
    const QColor red(0xB0, 0x00, 0x20);
    for (int row = 0; row < m_found.size() && row < m_table->rowCount(); ++row) {
        const FoundDevice &d = m_found.at(row);
        for (const auto &c : r.conflicts) {
            const int at = d.link == FoundDevice::Link::Can ? d.node : d.address;
            if (c.port != d.port || c.address != at)
                continue;
            for (int col = 0; col < ColConnect; ++col)
                if (QTableWidgetItem *item = m_table->item(row, col)) {
                    item->setForeground(red);
                    item->setToolTip(tr("Two devices at this address: %1").arg(c.evidence));
                }
        }
    }
    for (const auto &c : r.conflicts) {
        auto *item = new QListWidgetItem(tr("Conflict on %1, %2 %3: %4 What to do: %5")
                                             .arg(c.port, c.link == QLatin1String("can") ? tr("node") : tr("address"))
                                             .arg(c.address)
                                             .arg(c.evidence, c.advice),
                                         m_findings);
        item->setForeground(QColor(0xB0, 0x00, 0x20));
        QFont f = item->font();
        f.setBold(true);
        item->setFont(f);
    }
    for (const auto &n : r.notes) {
        QString kind;
        switch (n.kind) {
        case discovery::PortNote::Kind::Busy: kind = tr("busy"); break;
        case discovery::PortNote::Kind::Silent: kind = tr("silent"); break;
        case discovery::PortNote::Kind::Garbage: kind = tr("garbage"); break;
        case discovery::PortNote::Kind::NoPermission: kind = tr("no permission"); break;
        case discovery::PortNote::Kind::Failed: kind = tr("could not open"); break;
        case discovery::PortNote::Kind::OutOfTime: kind = tr("out of time"); break;
        case discovery::PortNote::Kind::Cancelled: kind = tr("cancelled"); break;
        }
        auto *item = new QListWidgetItem(tr("%1 (%2): %3").arg(n.port, kind, n.text), m_findings);
        item->setForeground(palette().color(QPalette::PlaceholderText));
    }
}

void FindDevicesDialog::onFinished()
{
    setRunning(false);
    showFindings();
    const discovery::SweepResult &r = m_sweep.result();
    QString text = tr("%n device(s) found", nullptr, int(r.devices.size())) + tr(" in %1 s.").arg(r.seconds, 0, 'f', 1);
    if (!r.conflicts.isEmpty())
        text += tr(" %n conflict(s): see below, in red.", nullptr, int(r.conflicts.size()));
    if (r.cancelled)
        text += tr(" Cancelled: what was found so far is listed.");
    m_status->setText(text);
    m_progress->setValue(m_progress->maximum());
}

QString FindDevicesDialog::statusText() const
{
    return m_status->text();
}

} // namespace imudesk::ui
