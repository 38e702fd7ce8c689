#pragma once
// Several devices recorded as one session (issue 36 point 3): a folder that holds each
// device's capture (docs/FILE_FORMATS.md, "Capture file format"), written by its own session as a single
// recording is, and session.json (record/session_manifest.h): the devices, their links and
// identities, the clock models they ended with, and what happened to each (a cable pulled, a
// recording stopped by a full disk). A device that drops out is marked there and the others go
// on; its capture keeps every byte it had received, and a device that comes back (the session
// reconnects by itself) goes on recording into the same file.
#include "device/session.h"
#include "device/session_types.h"
#include "capture/capture_header.h"
#include "record/session_manifest.h"

#include <QObject>
#include <QPointer>
#include <QString>

#include <vector>

namespace imudesk::device {

class GroupRecording : public QObject {
    Q_OBJECT
public:
    struct Member {
        Session *session = nullptr;
        QString label;   // a label the user set, or empty; the file and the manifest name the
                         // device by capture::deviceName (its serial, else family and address)
        QString address; // the link as the user gave it
        model::DeviceIdentity identity;
    };

    explicit GroupRecording(QObject *parent = nullptr);
    ~GroupRecording() override;

    // Creates the folder (it must not hold a session.json already) and starts every member's
    // recording (a member that is recording on its own already ends that recording first); false with a message when the folder cannot be made or no member started
    // (the ones that did are stopped again).
    bool start(const QString &folder, const std::vector<Member> &members, QString *error);
    // Stops every recording; finished() follows once all have stopped and session.json is written.
    void stop();
    bool running() const { return m_running; }
    QString folder() const { return m_folder; }
    // The manifest as it stands (devices, bytes, events so far).
    const record::SessionManifest &manifest() const { return m_manifest; }

Q_SIGNALS:
    void progress();
    // A device dropped out (or came back): its index in the members and what happened.
    void deviceEvent(int index, const QString &what);
    // All recordings stopped; session.json written (error: why it could not be, else empty).
    void finished(const QString &manifestPath, const QString &error);

private:
    void noteEvent(int index, const QString &what, const QString &detail);
    void onStopped(int index, const QString &reason);
    void writeManifest();

    struct Entry {
        QPointer<Session> session;
        bool recording = false; // asked to record and not stopped yet (started or starting)
        bool started = false;   // our recording started (a stop before it ends another one)
        QString path;           // our capture
        SessionStats lastStats;
        SessionState state = SessionState::Connected;
    };
    std::vector<Entry> m_entries;
    record::SessionManifest m_manifest;
    QString m_folder;
    bool m_running = false;
    bool m_stopping = false;
};

} // namespace imudesk::device
