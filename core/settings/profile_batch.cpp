#include "profile_batch.h"

#include "device/device_session.h"
#include "settings/setting_catalog.h"

#include <QTimer>

namespace imudesk::settings {

ProfileBatch::ProfileBatch(ConfigProfile profile, QStringList ports, QObject *parent)
    : QObject(parent), m_profile(std::move(profile)), m_ports(std::move(ports))
{
    qRegisterMetaType<DeviceReport>();
}

ProfileBatch::~ProfileBatch() = default;

void ProfileBatch::start()
{
    if (m_running)
        return;
    m_running = true;
    m_index = -1;
    m_reports.clear();
    next();
}

void ProfileBatch::next()
{
    m_controller.reset();
    m_session.reset();
    ++m_index;
    if (m_index >= m_ports.size()) {
        m_running = false;
        Q_EMIT finished();
        return;
    }
    m_current = DeviceReport{};
    m_deviceDone = false;
    m_current.port = m_ports.at(m_index);
    Q_EMIT deviceStarted(m_current.port);
    m_session = std::make_unique<device::DeviceSession>();
    m_session->setAutoReconnect(false);
    m_controller = std::make_unique<ConfigurationController>(*m_session);
    connect(m_session.get(), &device::DeviceSession::stateChanged, this,
            [this](device::SessionState s, const QString &detail) {
                if (s == device::SessionState::Failed || s == device::SessionState::Disconnected) {
                    if (m_controller && m_controller->busy())
                        return; // the flow in progress reports it
                    m_current.problems << tr("cannot connect: %1").arg(detail);
                    finishDevice();
                } else if (s == device::SessionState::Connected && m_baud <= 0 && !m_controller->busy()
                           && !m_controller->identity().usable()) {
                    onConnected(); // auto-detection read the identity already
                }
            });
    if (m_baud > 0)
        connect(m_session.get(), &device::DeviceSession::identityQueryFinished, this, [this](bool) { onConnected(); });
    connect(m_controller.get(), &ConfigurationController::readFinished, this, &ProfileBatch::onRead);
    connect(m_controller.get(), &ConfigurationController::applyFinished, this, &ProfileBatch::onApplied);
    connect(m_controller.get(), &ConfigurationController::actionFinished, this,
            [this](const QString &, bool ok, const QString &detail) {
                if (!ok) {
                    m_current.ok = false;
                    m_current.problems << tr("SAVECONFIG failed: %1").arg(detail);
                }
                finishDevice();
            });
    m_session->open(m_current.port, m_baud);
}

void ProfileBatch::onConnected()
{
    if (m_controller && !m_controller->busy())
        m_controller->readAll();
}

void ProfileBatch::onRead(bool ok, const QString &error)
{
    if (!ok) {
        m_current.problems << error;
        finishDevice();
        return;
    }
    const DeviceConfiguration &cfg = m_controller->configuration();
    m_current.serial = QString::fromStdString(cfg.identity.serial);
    m_current.product = QString::fromStdString(cfg.identity.productName);
    for (const auto &d : m_profile.diff(cfg))
        if (!d.applicable)
            m_current.problems << tr("%1=%2 not applied: %3").arg(d.key, d.profileValue, d.note);
    const auto changes = m_profile.changesFor(cfg);
    if (changes.empty()) {
        m_current.ok = true;
        if (m_save)
            m_controller->save();
        else
            finishDevice();
        return;
    }
    m_controller->apply(changes);
}

void ProfileBatch::onApplied(const ConfigurationController::ApplyReport &report)
{
    for (const auto &r : report.results) {
        if (r.outcome == ConfigurationController::Outcome::Verified)
            ++m_current.changed;
        else
            m_current.problems << tr("%1=%2: %3 %4")
                                      .arg(r.key, r.requested, ConfigurationController::outcomeName(r.outcome), r.detail)
                                      .trimmed();
    }
    if (!report.error.isEmpty())
        m_current.problems << report.error;
    m_current.ok = report.ok;
    bool unconfirmedOnly = !report.ok && report.error.isEmpty();
    for (const auto &r : report.results)
        unconfirmedOnly = unconfirmedOnly
                       && (r.outcome == ConfigurationController::Outcome::Verified
                           || r.outcome == ConfigurationController::Outcome::Unconfirmed);
    m_current.onlyUnconfirmed = unconfirmedOnly;
    if (report.ok && m_save)
        m_controller->save();
    else
        finishDevice();
}

void ProfileBatch::finishDevice()
{
    if (m_deviceDone)
        return;
    m_deviceDone = true;
    m_reports.push_back(m_current);
    Q_EMIT deviceFinished(m_current);
    // Not from inside the session's or controller's signal: they are destroyed in next().
    QTimer::singleShot(0, this, &ProfileBatch::next);
}

} // namespace imudesk::settings
