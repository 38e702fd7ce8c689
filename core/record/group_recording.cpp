#include "group_recording.h"

#include "record/recording.h"

#include "clock/host_clock.h"
#include "format/mcap/sample_channels.h"
#include "capture/device_name.h"

#include <QDateTime>
#include <QDir>
#include <QFileInfo>

#include <set>

namespace imudesk::device {

namespace {

// A name that is safe as a file name and tells the device.
QString fileStem(const QString &name, int index)
{
    QString s;
    for (QChar c : name)
        s += c.isLetterOrNumber() || c == QLatin1Char('-') || c == QLatin1Char('_') ? c : QLatin1Char('_');
    return QStringLiteral("%1-%2").arg(index + 1, 2, 10, QLatin1Char('0')).arg(s.left(40));
}

} // namespace

GroupRecording::GroupRecording(QObject *parent) : QObject(parent) {}

GroupRecording::~GroupRecording()
{
    for (Entry &e : m_entries)
        if (e.session && e.recording)
            e.session->stopRecording();
}

bool GroupRecording::start(const QString &folder, const std::vector<Member> &members, QString *error)
{
    auto failWith = [&](const QString &why) {
        if (error)
            *error = why;
        return false;
    };
    if (m_running)
        return failWith(tr("A session recording is already running."));
    if (members.empty())
        return failWith(tr("No device to record: connect one first."));
    if (record::SessionManifest::isSessionFolder(folder))
        return failWith(tr("%1 already holds a recorded session; choose another folder.").arg(folder));
    if (!QDir().mkpath(folder))
        return failWith(tr("Cannot create the folder %1: check that the place exists and can be written to.").arg(folder));
    m_folder = folder;
    m_entries.clear();
    m_manifest = {};
    m_manifest.startedUtc = QDateTime::currentDateTimeUtc().toString(Qt::ISODateWithMs);
    m_manifest.startedHostNs = hostNowNs();
    m_stopping = false;
    int started = 0;
    QStringList refused;
    std::set<std::string> names;
    for (size_t i = 0; i < members.size(); ++i) {
        const Member &m = members[i];
        const int index = int(i);
        capture::CaptureHeader header;
        header.setIdentity(m.identity);
        if (m.session)
            m.session->describeLink(header);
        const std::string name = format::mcap::SampleChannels::uniqueName(
            capture::deviceName(header, m.label.toStdString()), [&names](const std::string &n) { return names.count(n) > 0; });
        names.insert(name);
        record::SessionManifest::Device d;
        d.name = QString::fromStdString(name);
        d.address = m.address;
        d.linkKind = m.session ? m.session->linkKind() : QString();
        d.file = fileStem(d.name, index) + QStringLiteral(".imucap");
        d.product = QString::fromStdString(m.identity.productName);
        d.serial = QString::fromStdString(m.identity.serial);
        d.firmware = m.identity.firmware ? QString::fromStdString(m.identity.firmware->toString()) : QString();
        m_manifest.devices.push_back(d);
        Entry entry;
        entry.session = m.session;
        entry.state = m.session ? m.session->state() : SessionState::Closed;
        m_entries.push_back(entry);
        Session *s = m.session;
        if (!s) {
            refused << d.name;
            continue;
        }
        const QString path = QDir(folder).filePath(d.file);
        connect(s, &Session::recordingStarted, this, [this, index, path](const QString &started) {
            if (started == path)
                m_entries[size_t(index)].started = true;
            Q_EMIT progress();
        });
        connect(s, &Session::recordingProgress, this, [this, index](quint64 bytes, quint64 frames) {
            m_manifest.devices[size_t(index)].bytes = bytes;
            m_manifest.devices[size_t(index)].frames = frames;
            Q_EMIT progress();
        });
        connect(s, &Session::recordingStopped, this, [this, index](const QString &reason) {
            // The end of a recording the tab had made itself, before ours started: not ours.
            if (m_entries[size_t(index)].started)
                onStopped(index, reason);
        });
        // A tab closed (its session deleted) while recording: its capture ends there.
        connect(s, &QObject::destroyed, this, [this, index] {
            if (m_entries[size_t(index)].recording)
                onStopped(index, tr("The device's tab was closed or its link replaced; its capture ends here."));
        });
        connect(s, &DeviceLink::statsUpdated, this,
                [this, index](const SessionStats &st) { m_entries[size_t(index)].lastStats = st; });
        connect(s, &DeviceLink::stateChanged, this, [this, index](SessionState st, const QString &detail) {
            Entry &e = m_entries[size_t(index)];
            const SessionState was = std::exchange(e.state, st);
            if (!m_running || st == was)
                return;
            if (st == SessionState::Disconnected || st == SessionState::Reconnecting || st == SessionState::Failed) {
                if (was == SessionState::Connected)
                    noteEvent(index, QStringLiteral("disconnected"), detail);
            } else if (st == SessionState::Connected) {
                noteEvent(index, QStringLiteral("reconnected"), detail);
            }
        });
        m_entries.back().recording = true;
        m_entries.back().path = path;
        record::startRecording(*s, path);
        ++started;
    }
    if (started == 0)
        return failWith(tr("None of the devices could be recorded: %1.").arg(refused.join(QStringLiteral(", "))));
    m_running = true;
    writeManifest(); // a recording cut short by a crash still says what its files are
    return true;
}

void GroupRecording::stop()
{
    if (!m_running || m_stopping)
        return;
    m_stopping = true;
    bool any = false;
    for (size_t i = 0; i < m_entries.size(); ++i) {
        Entry &e = m_entries[i];
        if (!e.recording)
            continue;
        if (e.session) {
            any = true;
            e.session->stopRecording();
        } else { // its session went away without saying so
            e.recording = false;
        }
    }
    if (!any)
        onStopped(-1, QString());
}

void GroupRecording::noteEvent(int index, const QString &what, const QString &detail)
{
    m_manifest.devices[size_t(index)].events.push_back({hostNowNs(), what, detail});
    Q_EMIT deviceEvent(index, what);
    writeManifest();
}

void GroupRecording::onStopped(int index, const QString &reason)
{
    if (index >= 0) {
        Entry &e = m_entries[size_t(index)];
        if (!e.recording)
            return;
        e.recording = false;
        if (e.session) // this group's connections end with its recording
            disconnect(e.session, nullptr, this, nullptr);
        // The disk filled, the file went away, the tab stopped it (Record, Disconnect): this one
        // stops, the others go on.
        if (!reason.isEmpty())
            noteEvent(index, QStringLiteral("recording stopped"), reason);
        else if (!m_stopping)
            noteEvent(index, QStringLiteral("recording stopped"),
                      tr("Stopped in the device's own tab (Record or Disconnect) before the session ended."));
    }
    for (const Entry &e : m_entries)
        if (e.recording)
            return;
    // Every recording has stopped (as asked, or each by its own fault).
    m_running = false;
    m_manifest.stoppedHostNs = hostNowNs();
    for (size_t i = 0; i < m_entries.size(); ++i)
        m_manifest.devices[i].clocks = m_entries[i].lastStats.clocks;
    QString error;
    if (!m_manifest.save(m_folder, &error))
        Q_EMIT finished(QString(), error);
    else
        Q_EMIT finished(QDir(m_folder).filePath(QLatin1String(record::SessionManifest::kFileName)), QString());
}

void GroupRecording::writeManifest()
{
    for (size_t i = 0; i < m_entries.size(); ++i)
        m_manifest.devices[i].clocks = m_entries[i].lastStats.clocks;
    QString ignored;
    m_manifest.save(m_folder, &ignored); // written again at the end; a failure there is reported
}

} // namespace imudesk::device
