// StationView's simulated tray (the demo and the tests): the session's tray of simulated
// modules (StationSession::startSimulatedTray), its ports checked, and the dialog that sets it up.
#include "ui/station/station_view.h"


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

bool StationView::startSimulatedTray(int count, bool withFaults, QString *error)
{
    if (!m_session->startSimulatedTray(count, withFaults, error))
        return false;
    // The tray is what is tested now: only its ports are checked (the list shows them already).
    const QStringList tray = m_session->simulatedPorts();
    for (int i = 0; i < m_ports->count(); ++i)
        m_ports->item(i)->setCheckState(tray.contains(m_ports->item(i)->data(Qt::UserRole).toString()) ? Qt::Checked
                                                                                                      : Qt::Unchecked);
    updateActions();
    return true;
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
