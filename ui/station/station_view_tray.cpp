// StationView's simulated tray (the demo and the tests): modules of the simulator on
// pseudo-terminals or in process, three of them with a fault, and the dialog that sets it up.
#include "ui/station/station_view.h"

#include "sim/hipnuc_serial_device.h"
#include "sim/pty_simulator.h"
#include "sim/simulated_transport.h"

#include <QCheckBox>
#include <QDialog>
#include <QDialogButtonBox>
#include <QFormLayout>
#include <QLabel>
#include <QListWidget>
#include <QSpinBox>
#include <QVBoxLayout>

#include <algorithm>

namespace imudesk::ui {

QStringList StationView::simulatedPorts() const
{
    return m_simPorts;
}

bool StationView::startSimulatedTray(int count, bool withFaults, QString *error)
{
    if (running()) {
        if (error)
            *error = tr("Wait for the run to end, or cancel it, before changing the simulated tray.");
        return false;
    }
    count = std::clamp(count, 1, int(kMaxTraySize));
    stopSimulatedTray();
    // The three faulty modules: spread over a tray of six or more, else the first ones.
    const auto faultAt = [count](int i) {
        const int step = count >= 6 ? 2 : 1, first = count >= 6 ? 1 : 0;
        if (i < first || (i - first) % step != 0)
            return -1;
        const int fault = (i - first) / step;
        return fault < 3 ? fault : -1;
    };
    QHash<QString, sim::SimOptions> inProcess; // port -> module, for an in-process tray
    for (int i = 0; i < count; ++i) {
        sim::SimOptions o;
        o.model = "HI14";
        o.firmware = "1.7.1";
        o.baud = kSimulatedBaud;
        o.seed = uint64_t(i + 1);
        o.faults.magCalFixture = true; // the tray turns every module while its MCAL collects
        QString note = tr("a good module");
        switch (withFaults ? faultAt(i) : -1) {
        case 0:
            o.faults.gyroNoiseFactor = sim::SimFaults::kNoisyGyroFactor;
            note = tr("a noisy gyro (%1 times the noise)").arg(sim::SimFaults::kNoisyGyroFactor);
            break;
        case 1:
            o.faults.mountingErrorDeg = {sim::SimFaults::kWrongMountingRollDeg, 0, 0};
            note = tr("mounted wrongly (on its side, roll %1°)").arg(sim::SimFaults::kWrongMountingRollDeg);
            break;
        case 2:
            o.firmware = "1.6.6";
            note = tr("old firmware");
            break;
        default: break;
        }
        QString port;
        if (m_simInProcess) {
            port = QStringLiteral("sim:tray-%1").arg(i + 1);
            inProcess.insert(port, o);
        } else {
            auto sim = std::make_unique<sim::PtySimulator>(o);
            QString why;
            if (!sim->start(&why)) {
                stopSimulatedTray();
                if (error)
                    *error = tr("The simulated modules could not start: %1").arg(why);
                return false;
            }
            port = sim->devicePath();
            m_sims.push_back(std::move(sim));
        }
        m_simPorts << port;
        m_simNotes.insert(port, tr("Simulated HI14 %1 of %2, firmware %3: %4")
                                    .arg(i + 1)
                                    .arg(count)
                                    .arg(QString::fromStdString(o.firmware), note));
    }
    if (m_simInProcess) {
        // A module just powered on at each connection (a re-run's module starts afresh, where
        // a pseudo-terminal's keeps running); null for any other port: a serial port.
        m_simTransports = [modules = std::move(inProcess),
                           scale = m_simTimeScale](const QString &port) -> std::unique_ptr<io::Transport> {
            const auto it = modules.constFind(port);
            if (it == modules.constEnd())
                return nullptr;
            auto link = std::make_unique<sim::SimulatedTransport>(std::make_unique<sim::HipnucSerialDevice>(*it));
            link->setTimeScale(scale);
            return link;
        };
    }
    refreshPorts();
    // The tray is what is tested now: only its ports are checked.
    for (int i = 0; i < m_ports->count(); ++i)
        m_ports->item(i)->setCheckState(m_simPorts.contains(m_ports->item(i)->data(Qt::UserRole).toString())
                                            ? Qt::Checked
                                            : Qt::Unchecked);
    updateActions();
    return true;
}

void StationView::setSimulatedTrayInProcess(bool inProcess, double timeScale)
{
    m_simInProcess = inProcess;
    m_simTimeScale = timeScale > 0 ? timeScale : 1.0;
}

void StationView::stopSimulatedTray()
{
    for (auto &sim : m_sims)
        sim->stop();
    m_sims.clear();
    m_simTransports = nullptr;
    if (m_simPorts.isEmpty())
        return;
    const QStringList gone = m_simPorts;
    m_simPorts.clear();
    m_simNotes.clear();
    if (!m_ports)
        return;
    for (int i = m_ports->count() - 1; i >= 0; --i)
        if (gone.contains(m_ports->item(i)->data(Qt::UserRole).toString()))
            delete m_ports->takeItem(i);
    updateActions();
}

void StationView::openTrayDialog()
{
    // Non-modal: the station keeps running while it is open.
    auto *dialog = new QDialog(this);
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    dialog->setWindowTitle(tr("Simulated tray"));
    auto *count = new QSpinBox(dialog);
    count->setObjectName(QStringLiteral("trayCount"));
    count->setRange(1, kMaxTraySize);
    count->setValue(kDemoTraySize);
    auto *faults = new QCheckBox(tr("Three with faults: a noisy gyro, a wrong mounting, firmware 1.6.6"), dialog);
    faults->setObjectName(QStringLiteral("trayFaults"));
    faults->setChecked(true);
    auto *about = new QLabel(tr("Simulated HI14 modules on pseudo-terminals, each on a rotation fixture (for the "
                                "magnetometer calibration). They stop when this window closes."),
                             dialog);
    about->setWordWrap(true);
    auto *buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, dialog);
    auto *form = new QFormLayout;
    form->addRow(tr("Modules:"), count);
    auto *layout = new QVBoxLayout(dialog);
    layout->addWidget(about);
    layout->addLayout(form);
    layout->addWidget(faults);
    layout->addWidget(buttons);
    connect(buttons, &QDialogButtonBox::accepted, dialog, &QDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, dialog, &QDialog::reject);
    connect(dialog, &QDialog::accepted, this, [this, count, faults] {
        QString error;
        if (!startSimulatedTray(count->value(), faults->isChecked(), &error))
            showError(error);
    });
    dialog->show();
}

} // namespace imudesk::ui
