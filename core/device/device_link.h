#pragma once
// What every connected device looks like to its users, whatever the family and the link
// (HiPNUC serial, HEC495 serial, Modbus RTU, CAN): a state, an identity, counters and a
// bounded store of samples. The live views (charts, attitude, values, status bar) bind
// to this interface only. Each family's session derives from it, keeps its worker in a
// private thread and emits these signals in the owner's thread.
#include "device/sample_store.h"
#include "device/session_types.h"
#include "device/text_reply.h"

#include <QFlags>
#include <QObject>
#include <QString>

#include <atomic>
#include <memory>

namespace imudesk::capture {
class CaptureHeader;
}

namespace imudesk::device {

class DeviceLink : public QObject {
    Q_OBJECT
public:
    explicit DeviceLink(QObject *parent = nullptr);
    ~DeviceLink() override;

    virtual void close() = 0;
    // Short name of the family and link, e.g. "HiPNUC serial", "HEC495 serial", "HiPNUC Modbus".
    virtual QString linkKind() const = 0;

    // What a link offers beyond state, identity, counters and samples. A workspace shows the
    // docks and menu entries that go with each, whatever the family.
    enum class Capability : unsigned {
        TextCommands = 1 << 0, // commands as typed text with replies (console, command log, version)
        Settings = 1 << 1,     // the settings table (settings::ConfigurationController), profiles, wizards
        Recording = 1 << 2,    // a capture of every byte received (Session::startRecording)
        RawBytes = 1 << 3,     // the bytes on the wire, both directions (Session::rawLog)
    };
    Q_DECLARE_FLAGS(Capabilities, Capability)
    virtual Capabilities capabilities() const { return {}; }
    // Samples stamped with the host clock as they arrive (false for a replayed capture, whose
    // host times are the recording's): a view can tell a value that stopped arriving by its age.
    virtual bool isLive() const { return true; }
    // Adds what names the device on its link beyond its identity to a header that names it
    // (capture/device_name.h): a CAN link's protocol and node. Nothing for the others.
    virtual void describeLink(capture::CaptureHeader &) const {}
    // True while the link still asks the device who it is after it connected (a HiPNUC module
    // opened at a known rate is Connected first and answers LOG VERSION after): its serial and
    // product, which name it in files and topics (capture/device_name.h), are not known yet.
    virtual bool identityPending() const { return false; }

    // Capability::TextCommands: a command as a person typed it (the console); the reply comes
    // in textReplied(id, ...). 0 when this link takes no text. The only place where command text
    // is parsed; every other caller uses the family's typed commands.
    virtual quint64 sendText(const QString &text, int timeoutMs = 1000);
    // The documented commands with representative arguments, for completing what is typed.
    virtual QStringList textCommands() const { return {}; }

    SampleStore &store() { return *m_store; }
    const SampleStore &store() const { return *m_store; }
    // The store for a reader in another thread that may outlive the link (the live bridge).
    std::shared_ptr<SampleStore> sharedStore() const { return m_store; }
    SessionState state() const { return m_state.load(); }

Q_SIGNALS:
    void stateChanged(imudesk::device::SessionState state, const QString &detail);
    void identityChanged(const imudesk::model::DeviceIdentity &identity);
    void statsUpdated(const imudesk::device::SessionStats &stats);
    void errorOccurred(const QString &message);
    // A condition of the stream shown while it lasts (not a modal error); empty: it is over.
    void streamWarning(const QString &message);
    // Capability::TextCommands: the outcome of a command sent as text, or of a typed command a
    // view showed as text (by the same id); and lines the device sent that answer no command.
    void textReplied(quint64 id, const imudesk::device::TextReply &reply);
    void textReceived(const QString &line);

protected:
    // Records the state and emits stateChanged; call from the owner's thread.
    void setState(SessionState s, const QString &detail);

private:
    std::shared_ptr<SampleStore> m_store = std::make_shared<SampleStore>();
    std::atomic<SessionState> m_state{SessionState::Closed};
};

Q_DECLARE_OPERATORS_FOR_FLAGS(DeviceLink::Capabilities)

// No device: what a workspace shows before anything is connected (closed, no capabilities).
class NoLink final : public DeviceLink {
public:
    using DeviceLink::DeviceLink;
    void close() override {}
    QString linkKind() const override { return QString(); }
};

} // namespace imudesk::device
