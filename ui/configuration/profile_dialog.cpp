#include "configuration/profile_dialog.h"

#include "device/device_session.h"

#include <QFileDialog>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QTableWidget>
#include <QVBoxLayout>

namespace imudesk::ui {

using settings::ConfigurationController;

ProfileDialog::ProfileDialog(device::DeviceSession &session, QWidget *parent)
    : QDialog(parent), m_controller(std::make_unique<ConfigurationController>(session))
{
    setWindowTitle(tr("Configuration profiles"));
    auto *layout = new QVBoxLayout(this);
    auto *bar = new QHBoxLayout;
    auto *read = new QPushButton(tr("Read device"), this);
    auto *save = new QPushButton(tr("Save device to profile…"), this);
    auto *load = new QPushButton(tr("Load profile…"), this);
    m_apply = new QPushButton(tr("Apply to this device"), this);
    bar->addWidget(read);
    bar->addWidget(save);
    bar->addWidget(load);
    bar->addWidget(m_apply);
    bar->addStretch(1);
    layout->addLayout(bar);
    m_status = new QLabel(this);
    m_status->setWordWrap(true);
    layout->addWidget(m_status);
    m_diff = new QTableWidget(0, 4, this);
    m_diff->setHorizontalHeaderLabels({tr("Setting"), tr("Profile"), tr("Device"), tr("Note")});
    m_diff->horizontalHeader()->setStretchLastSection(true);
    m_diff->setEditTriggers(QAbstractItemView::NoEditTriggers);
    layout->addWidget(m_diff, 2);

    auto *batchRow = new QHBoxLayout;
    batchRow->addWidget(new QLabel(tr("Other ports (comma-separated):"), this));
    m_ports = new QLineEdit(this);
    batchRow->addWidget(m_ports, 1);
    m_applyPorts = new QPushButton(tr("Apply and save to each"), this);
    batchRow->addWidget(m_applyPorts);
    layout->addLayout(batchRow);
    m_batchTable = new QTableWidget(0, 5, this);
    m_batchTable->setHorizontalHeaderLabels({tr("Port"), tr("Serial number"), tr("Product"), tr("Result"), tr("Details")});
    m_batchTable->horizontalHeader()->setStretchLastSection(true);
    m_batchTable->setEditTriggers(QAbstractItemView::NoEditTriggers);
    layout->addWidget(m_batchTable, 1);

    connect(read, &QPushButton::clicked, this, &ProfileDialog::readDevice);
    connect(save, &QPushButton::clicked, this, &ProfileDialog::onSaveClicked);
    connect(load, &QPushButton::clicked, this, &ProfileDialog::onLoadClicked);
    connect(m_apply, &QPushButton::clicked, this, &ProfileDialog::applyToDevice);
    connect(m_applyPorts, &QPushButton::clicked, this,
            [this] { applyToPorts(m_ports->text().split(QLatin1Char(','), Qt::SkipEmptyParts)); });
    connect(m_controller.get(), &ConfigurationController::configurationChanged, this, &ProfileDialog::refreshDiff);
    connect(m_controller.get(), &ConfigurationController::readFinished, this, [this](bool ok, const QString &why) {
        if (!ok)
            m_status->setText(why);
    });
    connect(m_controller.get(), &ConfigurationController::applyFinished, this,
            [this](const ConfigurationController::ApplyReport &r) {
                int verified = 0;
                for (const auto &c : r.results)
                    verified += c.outcome == ConfigurationController::Outcome::Verified ? 1 : 0;
                m_status->setText(r.ok ? tr("%1 settings applied and verified.").arg(verified)
                                       : tr("%1 of %2 settings verified. %3")
                                             .arg(verified)
                                             .arg(r.results.size())
                                             .arg(r.error));
                refreshDiff();
            });
    refreshDiff();
}

ProfileDialog::~ProfileDialog() = default;

QString ProfileDialog::statusText() const
{
    return m_status->text();
}

void ProfileDialog::readDevice()
{
    m_controller->readAll();
}

bool ProfileDialog::saveProfile(const QString &path, QString *error)
{
    if (!m_controller->identity().usable()) {
        if (error)
            *error = tr("read the device first");
        return false;
    }
    const auto p = settings::ConfigProfile::fromConfiguration(m_controller->configuration());
    QString why;
    const bool ok = p.save(path, &why);
    m_status->setText(ok ? tr("Saved %1 settings to %2.").arg(p.settings.size()).arg(path) : why);
    if (error)
        *error = why;
    return ok;
}

bool ProfileDialog::loadProfile(const QString &path, QString *error)
{
    QString why;
    auto p = settings::ConfigProfile::load(path, &why);
    if (!p) {
        m_status->setText(why);
        if (error)
            *error = why;
        return false;
    }
    m_profile = std::move(p);
    m_status->setText(tr("Loaded %1 (%2 settings, taken from %3 %4).")
                          .arg(path)
                          .arg(m_profile->settings.size())
                          .arg(m_profile->product, m_profile->serial));
    refreshDiff();
    return true;
}

void ProfileDialog::refreshDiff()
{
    m_diff->setRowCount(0);
    const bool ready = m_profile && m_controller->identity().usable();
    m_apply->setEnabled(ready && !m_controller->busy());
    m_applyPorts->setEnabled(m_profile.has_value() && !m_batch);
    if (!ready)
        return;
    const auto diffs = m_profile->diff(m_controller->configuration());
    for (const auto &d : diffs) {
        const int row = m_diff->rowCount();
        m_diff->insertRow(row);
        m_diff->setItem(row, 0, new QTableWidgetItem(d.key));
        m_diff->setItem(row, 1, new QTableWidgetItem(d.profileValue));
        m_diff->setItem(row, 2, new QTableWidgetItem(d.deviceValue));
        m_diff->setItem(row, 3, new QTableWidgetItem(d.applicable ? QString() : d.note));
        if (!d.applicable)
            for (int c = 0; c < 4; ++c)
                m_diff->item(row, c)->setFlags(Qt::ItemIsSelectable); // shown greyed: cannot be applied here
    }
    m_apply->setEnabled(!m_profile->changesFor(m_controller->configuration()).empty() && !m_controller->busy());
}

void ProfileDialog::applyToDevice()
{
    if (!m_profile || !m_controller->identity().usable())
        return;
    const auto changes = m_profile->changesFor(m_controller->configuration());
    if (changes.empty()) {
        m_status->setText(tr("The device already matches the profile."));
        return;
    }
    m_controller->apply(changes);
}

void ProfileDialog::applyToPorts(const QStringList &ports, bool save)
{
    if (!m_profile || m_batch || ports.isEmpty())
        return;
    QStringList trimmed;
    for (const QString &p : ports)
        trimmed << p.trimmed();
    m_batchTable->setRowCount(0);
    m_batch = std::make_unique<settings::ProfileBatch>(*m_profile, trimmed);
    m_batch->setSave(save);
    connect(m_batch.get(), &settings::ProfileBatch::deviceFinished, this,
            [this](const settings::ProfileBatch::DeviceReport &r) {
                const int row = m_batchTable->rowCount();
                m_batchTable->insertRow(row);
                m_batchTable->setItem(row, 0, new QTableWidgetItem(r.port));
                m_batchTable->setItem(row, 1, new QTableWidgetItem(r.serial));
                m_batchTable->setItem(row, 2, new QTableWidgetItem(r.product));
                m_batchTable->setItem(row, 3,
                                      new QTableWidgetItem(r.ok ? tr("OK (%1 changed)").arg(r.changed) : tr("FAILED")));
                m_batchTable->setItem(row, 4, new QTableWidgetItem(r.problems.join(QLatin1String("; "))));
            });
    connect(m_batch.get(), &settings::ProfileBatch::finished, this, [this] {
        m_batch.release()->deleteLater();
        refreshDiff();
        Q_EMIT batchFinished();
    });
    m_applyPorts->setEnabled(false);
    m_batch->start();
}

void ProfileDialog::onSaveClicked()
{
    const QString path = QFileDialog::getSaveFileName(this, tr("Save profile"), QString(),
                                                      tr("ImuDesk profiles (*.json)"));
    if (!path.isEmpty())
        saveProfile(path);
}

void ProfileDialog::onLoadClicked()
{
    const QString path = QFileDialog::getOpenFileName(this, tr("Load profile"), QString(),
                                                      tr("ImuDesk profiles (*.json)"));
    if (!path.isEmpty())
        loadProfile(path);
}

} // namespace imudesk::ui
