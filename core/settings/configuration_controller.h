#pragma once
// Configuration flows over one DeviceSession: read every setting (LOG VERSION, LOG
// COMCONFIG), apply changes (the commands are listed first, then sent one by one, then
// read back and compared), save, reboot, factory reset and the one-shot actions. After a
// failure (ERR, timeout) the configuration is read again, so what it shows is what the
// device holds. A baud change goes last and through DeviceSession::changeBaud. One flow
// at a time; lives in the session's owner thread.
#include "device/device_session.h"
#include "settings/device_configuration.h"

#include <QObject>
#include <QString>
#include <QStringList>

#include <functional>
#include <map>
#include <vector>

namespace imudesk::settings {

class ConfigurationController : public QObject {
    Q_OBJECT
public:
    struct Change {
        QString key;
        QString value; // anything SettingCatalog::normalize accepts; canonical after plan()
    };
    struct PendingCommand {
        QString key;
        protocol::hipnuc::Command command; // made by the typed builders (SettingCatalog::commands)
    };
    struct Plan {
        std::vector<Change> changes;           // canonical values
        std::vector<PendingCommand> commands;  // in sending order (a baud change last)
        QStringList errors;                    // refused changes: nothing is sent when not empty
        bool ok() const { return errors.isEmpty(); }
    };
    // Mismatch: the module reports another value; Unconfirmed: its reply to LOG COMCONFIG did
    // not say (a reply in a format ImuDesk does not understand, or no reply): the write may or
    // may not have been taken.
    enum class Outcome { Verified, Mismatch, Refused, Timeout, NotSent, Unconfirmed };
    struct ChangeResult {
        QString key;
        QString requested;
        QString deviceValue; // read back after applying (empty when the device did not report it)
        Outcome outcome = Outcome::NotSent;
        QString detail;
    };
    struct ApplyReport {
        bool ok = false;                 // every change verified
        std::vector<ChangeResult> results;
        QString error;                   // why the flow stopped (planning, busy, read-back)
    };

    static constexpr int kCommandTimeoutMs = device::DeviceSession::kBusyLinkReplyTimeoutMs;
    static constexpr int kReadTimeoutMs = 3000;
    static constexpr int kResetSettleMs = 500;

    explicit ConfigurationController(device::DeviceSession &session, QObject *parent = nullptr);

    // What the device holds, as last read (empty before readAll()).
    const DeviceConfiguration &configuration() const { return m_config; }
    const model::DeviceIdentity &identity() const { return m_config.identity; }
    bool busy() const { return m_busy; }

    // Checks the changes against the connected device (its identity from the last read)
    // and lists the commands; nothing is sent.
    Plan plan(const std::vector<Change> &changes) const;
    // The equivalent command line: imudesk-cli config PORT set KEY=VALUE ... [--save] [--reboot]
    static QString cliLine(const QString &port, const std::vector<Change> &changes, bool save, bool reboot);
    static QString outcomeName(Outcome o);

    void readAll();
    void apply(const std::vector<Change> &changes);
    void save();
    void reboot();
    void factoryReset();
    // ATT.RST.1/2/3/5, YAW (argument "MODE,DEG"), SAVECONFIG, REBOOT, FRESET.
    void runAction(const QString &key, const QString &argument = QString());

Q_SIGNALS:
    void busyChanged(bool busy);
    void commandSent(const QString &command);
    void replyReceived(const QString &command, const imudesk::protocol::hipnuc::AsciiReply &reply);
    void configurationChanged();
    void readFinished(bool ok, const QString &error);
    void applyFinished(const imudesk::settings::ConfigurationController::ApplyReport &report);
    void actionFinished(const QString &key, bool ok, const QString &detail);

private:
    using Reply = protocol::hipnuc::AsciiReply;
    using ReplyFn = std::function<void(const Reply &)>;

    void send(const protocol::hipnuc::Command &command, int timeoutMs, ReplyFn done);
    void onCommandFinished(quint64 id, const Reply &reply);
    // attempt: LOG VERSION is asked twice at most (a reply cut short by the module's streaming
    // is asked for again).
    void read(std::function<void(bool ok, const QString &error)> done, int attempt = 0);
    void sendChanges(size_t index);
    void finishApply();
    void afterReset(const QString &key, const QList<int> &bauds);
    void setBusy(bool on);
    bool refuseIfBusy(const QString &what);

    device::DeviceSession &m_session;
    DeviceConfiguration m_config;
    std::map<quint64, std::pair<QString, ReplyFn>> m_waiting;
    bool m_busy = false;

    // the apply in progress
    Plan m_plan;
    std::vector<ChangeResult> m_results;
    QString m_applyError;
    int m_baudTarget = 0;
};

} // namespace imudesk::settings

Q_DECLARE_METATYPE(imudesk::settings::ConfigurationController::ApplyReport)
