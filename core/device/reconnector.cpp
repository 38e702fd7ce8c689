#include "reconnector.h"

#include <QLoggingCategory>

#include <utility>

Q_DECLARE_LOGGING_CATEGORY(lcEngine)

namespace imudesk::device {

Reconnector::Reconnector(io::Transport &transport, QObject *parent) : QObject(parent), m_transport(transport)
{
    m_timer.setInterval(kPollMs);
    connect(&m_timer, &QTimer::timeout, this, &Reconnector::attempt);
}

void Reconnector::setEnabled(bool on)
{
    m_enabled = on;
    if (!on)
        stop();
}

void Reconnector::start(int baud, std::function<void()> reopened)
{
    if (!m_enabled)
        return;
    m_baud = baud;
    m_reopened = std::move(reopened);
    m_lastError.clear();
    m_timer.start();
}

void Reconnector::stop()
{
    m_timer.stop();
    m_reopened = {};
}

void Reconnector::attempt()
{
    QString error;
    if (!m_transport.reopen(m_baud, &error)) {
        // Just plugged in: udev may not have set the permissions yet. Keep trying.
        if (!error.isEmpty() && error != m_lastError)
            qCInfo(lcEngine) << "reconnect attempt failed:" << error;
        m_lastError = error;
        return;
    }
    m_timer.stop();
    ++m_count;
    if (const auto reopened = std::exchange(m_reopened, {}))
        reopened();
}

} // namespace imudesk::device
