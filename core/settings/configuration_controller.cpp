#include "configuration_controller.h"
#include "protocol/hipnuc/ascii_command.h"

#include "settings/setting_catalog.h"

#include <QLoggingCategory>

#include <memory>

Q_LOGGING_CATEGORY(lcSettings, "imudesk.core.settings")

namespace imudesk::settings {

ConfigurationController::ConfigurationController(device::DeviceSession &session, QObject *parent)
    : QObject(parent), m_session(session)
{
    qRegisterMetaType<ApplyReport>();
    connect(&m_session, &device::DeviceSession::commandFinished, this, &ConfigurationController::onCommandFinished);
}

QString ConfigurationController::outcomeName(Outcome o)
{
    switch (o) {
    case Outcome::Verified: return tr("verified");
    case Outcome::Mismatch: return tr("not taken (read back differs)");
    case Outcome::Refused: return tr("refused (ERR)");
    case Outcome::Timeout: return tr("no reply");
    case Outcome::NotSent: return tr("not sent");
    case Outcome::Unconfirmed: return tr("could not be read back");
    }
    return {};
}

ConfigurationController::Plan ConfigurationController::plan(const std::vector<Change> &changes) const
{
    Plan p;
    const model::DeviceIdentity &id = m_config.identity;
    if (!id.usable()) {
        p.errors << tr("the device has not been read yet (its model and firmware decide which settings exist)");
        return p;
    }
    std::vector<Change> merged; // one change per key, the last one wins
    for (const Change &c : changes) {
        const SettingDefinition *d = SettingCatalog::find(c.key);
        if (!d) {
            p.errors << tr("unknown setting '%1' (settings: %2)").arg(c.key, SettingCatalog::keys().join(QLatin1String(", ")));
            continue;
        }
        const QString key = QLatin1String(d->key);
        bool replaced = false;
        for (Change &m : merged)
            if (m.key == key) {
                m.value = c.value;
                replaced = true;
            }
        if (!replaced)
            merged.push_back({key, c.value});
    }
    std::optional<std::pair<Change, protocol::hipnuc::Command>> baud;
    for (const Change &c : merged) {
        const SettingDefinition *d = SettingCatalog::find(c.key);
        const auto a = SettingCatalog::availability(*d, id);
        if (!a.available) {
            p.errors << tr("%1: %2").arg(c.key, a.reason);
            continue;
        }
        QString error;
        const auto value = SettingCatalog::normalize(*d, c.value, &id, &error);
        const auto cmds = value ? SettingCatalog::commands(*d, *value, id, &error)
                                : std::vector<protocol::hipnuc::Command>();
        if (cmds.empty()) {
            p.errors << error;
            continue;
        }
        if (d->kind == SettingKind::Baud) {
            baud = std::make_pair(Change{c.key, *value}, cmds.front());
            continue;
        }
        p.changes.push_back({c.key, *value});
        p.commands.push_back({c.key, cmds.front()});
    }
    if (baud) {
        p.changes.push_back(baud->first);
        p.commands.push_back({baud->first.key, baud->second});
    }
    return p;
}

QString ConfigurationController::cliLine(const QString &port, const std::vector<Change> &changes, bool save,
                                         bool reboot)
{
    QStringList parts = {QStringLiteral("imudesk-cli"), QStringLiteral("config"), port, QStringLiteral("set")};
    for (const Change &c : changes) {
        QString arg = c.key + QLatin1Char('=') + c.value;
        if (arg.contains(QLatin1Char(' ')))
            arg = QLatin1Char('"') + arg + QLatin1Char('"');
        parts << arg;
    }
    if (save)
        parts << QStringLiteral("--save");
    if (reboot)
        parts << QStringLiteral("--reboot");
    return parts.join(QLatin1Char(' '));
}

void ConfigurationController::setBusy(bool on)
{
    if (m_busy == on)
        return;
    m_busy = on;
    Q_EMIT busyChanged(on);
}

bool ConfigurationController::refuseIfBusy(const QString &what)
{
    if (!m_busy)
        return false;
    qCWarning(lcSettings) << "refused while busy:" << what;
    return true;
}

void ConfigurationController::send(const protocol::hipnuc::Command &command, int timeoutMs, ReplyFn done)
{
    const QString text = QString::fromStdString(command.text);
    QString error;
    const quint64 id = m_session.sendCommand(command, timeoutMs, &error);
    Q_EMIT commandSent(text);
    if (id == 0) { // refused by its builder: answered at once, as the device would not be asked
        Reply refused;
        refused.command = command.text;
        refused.status = Reply::Status::NotSent;
        refused.errorLine = error.toStdString();
        Q_EMIT replyReceived(text, refused);
        done(refused);
        return;
    }
    m_waiting[id] = {text, std::move(done)};
}

void ConfigurationController::onCommandFinished(quint64 id, const Reply &reply)
{
    const auto it = m_waiting.find(id);
    if (it == m_waiting.end())
        return;
    auto [command, done] = std::move(it->second);
    m_waiting.erase(it);
    Q_EMIT replyReceived(command, reply);
    done(reply);
}

void ConfigurationController::read(std::function<void(bool, const QString &)> done, int attempt)
{
    send(protocol::hipnuc::commands::logVersion(), kCommandTimeoutMs, [this, done, attempt](const Reply &r) {
        if (r.ok()) {
            const auto id = model::DeviceIdentity::fromKeyValues(r.values);
            if (id.usable())
                m_config.identity = id;
        }
        if (!m_config.identity.usable() && attempt == 0 && (r.ok() || r.status == Reply::Status::Timeout)) {
            // An answer without model or firmware (its lines cut by frames of the module's
            // output), or none: asked once more before giving up.
            read(done, 1);
            return;
        }
        if (!m_config.identity.usable()) {
            done(false, tr("the device did not tell its model and firmware (LOG VERSION: %1)")
                            .arg(r.ok() ? tr("incomplete reply") : QString::fromStdString(r.errorLine)));
            return;
        }
        send(protocol::hipnuc::commands::logComConfig(), kReadTimeoutMs, [this, done](const Reply &c) {
            if (!c.ok()) {
                done(false, tr("LOG COMCONFIG failed (%1): the settings shown may be out of date")
                                .arg(c.errorLine.empty() ? QString::fromLatin1(model::outcomeName(c.status))
                                                         : QString::fromStdString(c.errorLine)));
                return;
            }
            const model::DeviceIdentity id = m_config.identity;
            m_config = DeviceConfiguration::fromComConfig(id, c.values);
            for (const std::string &line : c.lines)
                m_config.rawLines << QString::fromStdString(line);
            Q_EMIT configurationChanged();
            done(true, QString());
        });
    });
}

void ConfigurationController::readAll()
{
    if (refuseIfBusy(QStringLiteral("read"))) {
        Q_EMIT readFinished(false, tr("another configuration step is still running"));
        return;
    }
    setBusy(true);
    read([this](bool ok, const QString &error) {
        setBusy(false);
        Q_EMIT readFinished(ok, error);
    });
}

void ConfigurationController::apply(const std::vector<Change> &changes)
{
    if (refuseIfBusy(QStringLiteral("apply"))) {
        Q_EMIT applyFinished({false, {}, tr("another configuration step is still running")});
        return;
    }
    m_plan = plan(changes);
    if (!m_plan.ok()) {
        Q_EMIT applyFinished({false, {}, m_plan.errors.join(QLatin1String("; "))});
        return;
    }
    setBusy(true);
    m_results.clear();
    m_applyError.clear();
    for (const Change &c : m_plan.changes)
        m_results.push_back({c.key, c.value, {}, Outcome::NotSent, {}});
    sendChanges(0);
}

void ConfigurationController::sendChanges(size_t index)
{
    if (index >= m_plan.commands.size()) {
        finishApply();
        return;
    }
    const SettingDefinition *d = SettingCatalog::find(m_plan.commands[index].key);
    if (d && d->kind == SettingKind::Baud) {
        const int baud = m_plan.changes[index].value.toInt();
        Q_EMIT commandSent(QString::fromStdString(m_plan.commands[index].command.text));
        auto conn = std::make_shared<QMetaObject::Connection>();
        *conn = connect(&m_session, &device::DeviceSession::baudChangeFinished, this,
                        [this, conn, index](bool changed, int at, const QString &detail) {
                            disconnect(*conn);
                            ChangeResult &r = m_results[index];
                            r.detail = detail;
                            if (!changed)
                                r.outcome = at > 0 ? Outcome::Refused : Outcome::Timeout;
                            else
                                r.outcome = Outcome::Verified; // confirmed below by the read-back as well
                            if (at <= 0)
                                m_applyError = detail;
                            finishApply();
                        });
        m_session.changeBaud(baud);
        return;
    }
    send(m_plan.commands[index].command, kCommandTimeoutMs, [this, index](const Reply &r) {
        ChangeResult &res = m_results[index];
        if (r.ok()) {
            res.outcome = Outcome::Verified; // provisional: the read-back decides
            sendChanges(index + 1);
            return;
        }
        res.outcome = r.status == Reply::Status::Refused ? Outcome::Refused
            : r.status == Reply::Status::Timeout       ? Outcome::Timeout
                                                        : Outcome::NotSent;
        res.detail = r.status == Reply::Status::Refused
            ? tr("the device answered %1").arg(QString::fromStdString(r.errorLine))
            : QString::fromStdString(r.errorLine);
        // The rest is not sent: the device's state is read back as it is now.
        finishApply();
    });
}

void ConfigurationController::finishApply()
{
    read([this](bool ok, const QString &error) {
        ApplyReport report;
        report.error = m_applyError;
        if (!ok && report.error.isEmpty())
            report.error = error;
        // What the reply showed, for a setting it did not name (at most a few lines).
        QStringList shown = m_config.rawLines.mid(0, 4);
        if (m_config.rawLines.size() > 4)
            shown << QStringLiteral("…");
        const QString raw = shown.isEmpty() ? tr("an empty reply") : shown.join(QStringLiteral(" | "));
        for (ChangeResult &r : m_results) {
            const auto v = m_config.value(r.key);
            r.deviceValue = v.value_or(QString());
            if (r.outcome != Outcome::Verified)
                continue;
            if (!ok) {
                // No reply to read back from: neither taken nor refused, as far as anyone knows.
                r.outcome = Outcome::Unconfirmed;
                if (r.detail.isEmpty())
                    r.detail = tr("the module did not answer the read-back (%1); check it with LOG COMCONFIG").arg(error);
            } else if (!v) {
                // The reply does not name the setting in a form ImuDesk reads: say so, with the
                // reply, instead of "not taken".
                r.outcome = Outcome::Unconfirmed;
                if (r.detail.isEmpty())
                    r.detail = tr("LOG COMCONFIG did not report %1 in a form ImuDesk reads; the reply was: %2")
                                   .arg(QLatin1String(SettingCatalog::find(r.key)->comConfigKey), raw);
            } else if (*v != r.requested) {
                r.outcome = Outcome::Mismatch;
                if (r.detail.isEmpty())
                    r.detail = tr("the device reports %1").arg(*v);
            }
        }
        report.results = m_results;
        report.ok = ok && report.error.isEmpty();
        for (const ChangeResult &r : m_results)
            report.ok = report.ok && r.outcome == Outcome::Verified;
        setBusy(false);
        Q_EMIT applyFinished(report);
    });
}

void ConfigurationController::save()
{
    runAction(QStringLiteral("SAVECONFIG"));
}

void ConfigurationController::reboot()
{
    runAction(QStringLiteral("REBOOT"));
}

void ConfigurationController::factoryReset()
{
    runAction(QStringLiteral("FRESET"));
}

void ConfigurationController::runAction(const QString &key, const QString &argument)
{
    const ActionDefinition *a = SettingCatalog::findAction(key);
    if (!a) {
        Q_EMIT actionFinished(key, false, tr("unknown action '%1'").arg(key));
        return;
    }
    const QString name = QLatin1String(a->key);
    if (refuseIfBusy(name)) {
        Q_EMIT actionFinished(name, false, tr("another configuration step is still running"));
        return;
    }
    if (m_config.identity.usable()) {
        const auto av = SettingCatalog::availability(*a, m_config.identity);
        if (!av.available) {
            Q_EMIT actionFinished(name, false, tr("%1: %2").arg(name, av.reason));
            return;
        }
    }
    QString error;
    const auto command = SettingCatalog::actionCommand(*a, argument, &error);
    if (!command) {
        Q_EMIT actionFinished(name, false, error);
        return;
    }
    setBusy(true);
    send(*command, kCommandTimeoutMs, [this, name](const Reply &r) {
        if (!r.ok()) {
            setBusy(false);
            Q_EMIT actionFinished(name, false,
                                  r.status == Reply::Status::Refused
                                      ? tr("the device answered %1").arg(QString::fromStdString(r.errorLine))
                                      : QString::fromStdString(r.errorLine));
            return;
        }
        if (name == QLatin1String("REBOOT"))
            afterReset(name, {});
        else if (name == QLatin1String("FRESET"))
            afterReset(name, {115200});
        else {
            setBusy(false);
            Q_EMIT actionFinished(name, true, QString());
        }
    });
}

void ConfigurationController::afterReset(const QString &key, const QList<int> &bauds)
{
    auto conn = std::make_shared<QMetaObject::Connection>();
    *conn = connect(&m_session, &device::DeviceSession::linkRecovered, this,
                    [this, conn, key](bool reachable, int baud, const QString &detail) {
                        disconnect(*conn);
                        if (!reachable) {
                            setBusy(false);
                            Q_EMIT actionFinished(key, false, detail);
                            return;
                        }
                        qCInfo(lcSettings) << key << "done; the device answers at" << baud;
                        read([this, key](bool ok, const QString &error) {
                            setBusy(false);
                            Q_EMIT actionFinished(key, ok, error);
                        });
                    });
    m_session.recoverLink(bauds, kResetSettleMs);
}

} // namespace imudesk::settings
