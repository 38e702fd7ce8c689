// imudesk-cli config: read, set, export, diff and apply device settings (core/settings).
#include "cli_context.h"
#include "settings/bandwidth_calculator.h"
#include "settings/config_profile.h"
#include "settings/configuration_controller.h"
#include "settings/profile_batch.h"
#include "settings/setting_catalog.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>

#include <cstdio>

namespace imudesk::cli {

namespace {

using settings::ConfigurationController;
using settings::SettingCatalog;

const char *kUsage = "imudesk-cli config PORT [--baud B] [--json]\n"
                     "       imudesk-cli config PORT set KEY=VALUE... [--save] [--reboot] [--dry-run]\n"
                     "       imudesk-cli config PORT action NAME[=ARG]   (ATT.RST.1/2/3/5, YAW=MODE,DEG, SAVECONFIG, "
                     "REBOOT, FRESET)\n"
                     "       imudesk-cli config PORT export PROFILE.json\n"
                     "       imudesk-cli config PORT diff PROFILE.json [--json]\n"
                     "       imudesk-cli config PORT[,PORT...] apply PROFILE.json [--save]";

struct Device {
    device::DeviceSession session;
    ConfigurationController controller{session};
    int baud = 0;
};

bool connectAndRead(Device &d, const QString &port, int baud, QString *error)
{
    model::DeviceIdentity id;
    if (!connectSession(d.session, port, baud, &id, &d.baud, error))
        return false;
    bool done = false, ok = false;
    QObject::connect(&d.controller, &ConfigurationController::readFinished, &d.controller,
                     [&](bool good, const QString &why) {
                         done = true;
                         ok = good;
                         if (!good)
                             *error = why;
                     });
    d.controller.readAll();
    if (!waitFor([&] { return done; }, 15000) && !done)
        *error = interrupted() ? QStringLiteral("interrupted") : QStringLiteral("reading the settings timed out");
    return ok;
}

bool runAction(Device &d, const QString &name, const QString &arg, QString *detail)
{
    bool done = false, ok = false;
    auto c = QObject::connect(&d.controller, &ConfigurationController::actionFinished, &d.controller,
                              [&](const QString &, bool good, const QString &why) {
                                  done = true;
                                  ok = good;
                                  *detail = why;
                              });
    d.controller.runAction(name, arg);
    waitFor([&] { return done; }, 30000);
    QObject::disconnect(c);
    if (!done)
        *detail = QStringLiteral("no answer within 30 s");
    return ok;
}

ConfigurationController::ApplyReport runApply(Device &d, const std::vector<ConfigurationController::Change> &changes)
{
    bool done = false;
    ConfigurationController::ApplyReport report;
    auto c = QObject::connect(&d.controller, &ConfigurationController::applyFinished, &d.controller,
                              [&](const ConfigurationController::ApplyReport &r) {
                                  done = true;
                                  report = r;
                              });
    d.controller.apply(changes);
    waitFor([&] { return done; }, 60000);
    QObject::disconnect(c);
    if (!done)
        report.error = QStringLiteral("no answer within 60 s");
    return report;
}

QJsonObject identityJson(const model::DeviceIdentity &id)
{
    QJsonObject o;
    o[QStringLiteral("product")] = QString::fromStdString(id.productName);
    o[QStringLiteral("firmware")] = id.firmware ? QString::fromStdString(id.firmware->toString()) : QString();
    o[QStringLiteral("serial")] = QString::fromStdString(id.serial);
    o[QStringLiteral("family")] = QString::fromLatin1(model::familyName(id.family()));
    return o;
}

void printBandwidth(const settings::BandwidthCalculator::Result &r)
{
    if (!r.warning.isEmpty())
        std::fprintf(stderr, "imudesk-cli: warning: %s\n", r.warning.toLocal8Bit().constData());
}

int showConfig(Device &d, const QString &port, bool json)
{
    const auto &cfg = d.controller.configuration();
    const auto bw = settings::BandwidthCalculator::evaluate(cfg);
    if (json) {
        QJsonObject values, unavailable;
        for (const auto &def : SettingCatalog::settings()) {
            const QString key = QLatin1String(def.key);
            const auto a = SettingCatalog::availability(def, cfg.identity);
            if (!a.available)
                unavailable[key] = a.reason;
            else if (const auto v = cfg.value(key))
                values[key] = *v;
        }
        QJsonObject o;
        o[QStringLiteral("port")] = port;
        o[QStringLiteral("baud")] = d.baud;
        o[QStringLiteral("device")] = identityJson(cfg.identity);
        o[QStringLiteral("settings")] = values;
        o[QStringLiteral("unavailable")] = unavailable;
        QJsonObject load;
        load[QStringLiteral("bytes_per_second")] = bw.bytesPerSecond;
        load[QStringLiteral("capacity")] = bw.capacityBytesPerSecond;
        load[QStringLiteral("load")] = bw.load;
        load[QStringLiteral("fits")] = bw.fits;
        o[QStringLiteral("link")] = load;
        out(QString::fromUtf8(QJsonDocument(o).toJson(QJsonDocument::Compact)));
        return ExitOk;
    }
    out(QStringLiteral("# %1 %2 firmware %3 serial %4 at %5 baud")
            .arg(port, QString::fromStdString(cfg.identity.productName),
                 cfg.identity.firmware ? QString::fromStdString(cfg.identity.firmware->toString()) : QString(),
                 QString::fromStdString(cfg.identity.serial))
            .arg(d.baud));
    for (const auto &def : SettingCatalog::settings()) {
        const auto v = cfg.value(QLatin1String(def.key));
        if (!v)
            continue;
        out(QStringLiteral("%1=%2\t# %3: %4")
                .arg(QLatin1String(def.key), *v, SettingCatalog::label(def), SettingCatalog::valueText(def, *v)));
    }
    out(QStringLiteral("# link: %1 of %2 bytes/s (%3 %)")
            .arg(bw.bytesPerSecond, 0, 'f', 0)
            .arg(bw.capacityBytesPerSecond, 0, 'f', 0)
            .arg(bw.load * 100.0, 0, 'f', 0));
    for (const QString &line : cfg.unreadable)
        out(QStringLiteral("# not understood: %1").arg(line));
    printBandwidth(bw);
    return ExitOk;
}

int printReport(const ConfigurationController::ApplyReport &r)
{
    for (const auto &c : r.results)
        out(QStringLiteral("%1=%2\t%3%4")
                .arg(c.key, c.requested, ConfigurationController::outcomeName(c.outcome),
                     c.detail.isEmpty() ? QString() : QStringLiteral(" (%1)").arg(c.detail)));
    if (r.ok)
        return ExitOk;
    // Only unconfirmed (the read-back said nothing) and no other failure: exit 3, not 1.
    bool onlyUnconfirmed = r.error.isEmpty();
    for (const auto &c : r.results)
        onlyUnconfirmed = onlyUnconfirmed
                       && (c.outcome == ConfigurationController::Outcome::Verified
                           || c.outcome == ConfigurationController::Outcome::Unconfirmed);
    if (onlyUnconfirmed)
        return fail(QStringLiteral("written, but the module's LOG COMCONFIG reply did not confirm every setting (see above)"),
                    ExitUnconfirmed);
    return fail(r.error.isEmpty() ? QStringLiteral("not every setting was taken (see above)") : r.error);
}

int cmdSet(Device &d, const QString &port, const QStringList &assignments, bool save, bool reboot, bool dryRun)
{
    std::vector<ConfigurationController::Change> changes;
    for (const QString &a : assignments) {
        const qsizetype eq = a.indexOf(QLatin1Char('='));
        if (eq <= 0)
            return fail(QStringLiteral("'%1' is not KEY=VALUE (e.g. IMU.URFR=205)").arg(a), ExitUsage);
        changes.push_back({a.left(eq), a.mid(eq + 1)});
    }
    const auto plan = d.controller.plan(changes);
    if (!plan.ok())
        return fail(plan.errors.join(QLatin1String("; ")), ExitUsage);
    // What the link will carry once the changes are in.
    settings::DeviceConfiguration after = d.controller.configuration();
    for (const auto &c : plan.changes)
        after.values[c.key] = c.value;
    printBandwidth(settings::BandwidthCalculator::evaluate(after));
    for (const auto &c : plan.commands)
        out(QStringLiteral("> %1").arg(QString::fromStdString(c.command.text)));
    if (save)
        out(QStringLiteral("> %1").arg(QString::fromStdString(protocol::hipnuc::commands::saveConfig().text)));
    if (reboot)
        out(QStringLiteral("> %1").arg(QString::fromStdString(protocol::hipnuc::commands::reboot().text)));
    if (dryRun) {
        out(QStringLiteral("# %1").arg(ConfigurationController::cliLine(port, plan.changes, save, reboot)));
        return ExitOk;
    }
    const auto report = runApply(d, plan.changes);
    const int rc = printReport(report);
    if (rc != ExitOk)
        return rc;
    QString detail;
    if (save && !runAction(d, QStringLiteral("SAVECONFIG"), QString(), &detail))
        return fail(QStringLiteral("SAVECONFIG failed: %1").arg(detail));
    if (reboot) {
        if (!runAction(d, QStringLiteral("REBOOT"), QString(), &detail))
            return fail(QStringLiteral("REBOOT: %1").arg(detail));
        // After the reset: what the device holds now.
        for (const auto &c : plan.changes) {
            const auto v = d.controller.configuration().value(c.key);
            if (!v || *v != c.value)
                return fail(QStringLiteral("after REBOOT %1 is %2, not %3 (was it saved? add --save)")
                                .arg(c.key, v.value_or(QStringLiteral("unknown")), c.value));
        }
        out(QStringLiteral("# after REBOOT every setting reads back as set"));
    }
    return ExitOk;
}

int cmdDiff(Device &d, const QString &path, bool json)
{
    QString error;
    const auto profile = settings::ConfigProfile::load(path, &error);
    if (!profile)
        return fail(error);
    const auto diffs = profile->diff(d.controller.configuration());
    if (json) {
        QJsonArray arr;
        for (const auto &x : diffs) {
            QJsonObject o;
            o[QStringLiteral("key")] = x.key;
            o[QStringLiteral("profile")] = x.profileValue;
            o[QStringLiteral("device")] = x.deviceValue;
            o[QStringLiteral("applicable")] = x.applicable;
            if (!x.note.isEmpty())
                o[QStringLiteral("note")] = x.note;
            arr.append(o);
        }
        out(QString::fromUtf8(QJsonDocument(arr).toJson(QJsonDocument::Compact)));
    } else {
        for (const auto &x : diffs)
            out(QStringLiteral("%1\tprofile %2\tdevice %3%4")
                    .arg(x.key, x.profileValue, x.deviceValue.isEmpty() ? QStringLiteral("-") : x.deviceValue,
                         x.applicable ? QString() : QStringLiteral("\t(%1)").arg(x.note)));
        if (diffs.empty())
            out(QStringLiteral("# the device matches the profile"));
    }
    return diffs.empty() ? ExitOk : ExitFailure;
}

int cmdApply(const QStringList &ports, int baud, const QString &path, bool save)
{
    QString error;
    const auto profile = settings::ConfigProfile::load(path, &error);
    if (!profile)
        return fail(error);
    settings::ProfileBatch batch(*profile, ports);
    batch.setBaud(baud);
    batch.setSave(save);
    QObject::connect(&batch, &settings::ProfileBatch::deviceFinished, &batch,
                     [](const settings::ProfileBatch::DeviceReport &r) {
                         out(QStringLiteral("%1\t%2\t%3\t%4\t%5 changed%6")
                                 .arg(r.port, r.serial.isEmpty() ? QStringLiteral("-") : r.serial,
                                      r.product.isEmpty() ? QStringLiteral("-") : r.product,
                                      r.ok                  ? QStringLiteral("OK")
                                      : r.onlyUnconfirmed   ? QStringLiteral("UNCONFIRMED")
                                                            : QStringLiteral("FAILED"))
                                 .arg(r.changed)
                                 .arg(r.problems.isEmpty() ? QString()
                                                           : QStringLiteral("\t") + r.problems.join(QLatin1String("; "))));
                     });
    batch.start();
    waitFor([&] { return !batch.running(); }, -1);
    if (interrupted())
        return fail(QStringLiteral("interrupted"), ExitInterrupted);
    int failed = 0, unconfirmed = 0;
    for (const auto &r : batch.reports()) {
        failed += r.ok || r.onlyUnconfirmed ? 0 : 1;
        unconfirmed += !r.ok && r.onlyUnconfirmed ? 1 : 0;
    }
    if (failed)
        return fail(QStringLiteral("%1 of %2 devices failed").arg(failed).arg(batch.reports().size()));
    if (unconfirmed)
        return fail(QStringLiteral("%1 of %2 devices: written, but their LOG COMCONFIG reply did not confirm every setting")
                        .arg(unconfirmed)
                        .arg(batch.reports().size()),
                    ExitUnconfirmed);
    return ExitOk;
}

} // namespace

int cmdConfig(const QStringList &args)
{
    QCommandLineParser p;
    p.addOption({QStringLiteral("baud"), QStringLiteral("Baud rate (default: auto-detect)."), QStringLiteral("B")});
    p.addOption({QStringLiteral("json"), QStringLiteral("Machine-readable JSON output.")});
    p.addOption({QStringLiteral("save"), QStringLiteral("SAVECONFIG after the settings were verified.")});
    p.addOption({QStringLiteral("reboot"), QStringLiteral("REBOOT afterwards and read every setting back.")});
    p.addOption({QStringLiteral("dry-run"), QStringLiteral("Only list the commands that would be sent.")});
    p.addPositionalArgument(QStringLiteral("PORT"), QStringLiteral("Serial port, e.g. /dev/ttyUSB0"));
    p.addPositionalArgument(QStringLiteral("SUBCOMMAND"), QStringLiteral("set, action, export, diff or apply"));
    if (!parseArgs(p, args, QString::fromLatin1(kUsage)))
        return ExitUsage;
    const QStringList pos = p.positionalArguments();
    if (pos.isEmpty())
        return fail(QStringLiteral("config needs a PORT (usage: %1)").arg(QString::fromLatin1(kUsage)), ExitUsage);
    int baud = 0;
    if (p.isSet(QStringLiteral("baud"))) {
        bool ok = false;
        baud = p.value(QStringLiteral("baud")).toInt(&ok);
        if (!ok || baud <= 0)
            return fail(QStringLiteral("--baud needs a positive number"), ExitUsage);
    }
    const QString port = pos.at(0);
    const QString sub = pos.size() > 1 ? pos.at(1) : QString();
    const QStringList rest = pos.mid(2);
    if (!sub.isEmpty() && sub != QLatin1String("set") && sub != QLatin1String("action")
        && sub != QLatin1String("export") && sub != QLatin1String("diff") && sub != QLatin1String("apply"))
        return fail(QStringLiteral("unknown config subcommand '%1' (set, action, export, diff, apply)").arg(sub),
                    ExitUsage);
    if ((sub == QLatin1String("export") || sub == QLatin1String("diff") || sub == QLatin1String("apply")
         || sub == QLatin1String("action"))
        && rest.size() != 1)
        return fail(QStringLiteral("config %1 needs exactly one argument").arg(sub), ExitUsage);
    if (sub == QLatin1String("set") && rest.isEmpty())
        return fail(QStringLiteral("config set needs KEY=VALUE arguments, e.g. IMU.URFR=205"), ExitUsage);
    if (sub == QLatin1String("apply"))
        return cmdApply(port.split(QLatin1Char(','), Qt::SkipEmptyParts), baud, rest.front(),
                        p.isSet(QStringLiteral("save")));

    Device d;
    QString error;
    if (!connectAndRead(d, port, baud, &error))
        return fail(error, interrupted() ? ExitInterrupted : ExitFailure);
    if (sub.isEmpty())
        return showConfig(d, port, p.isSet(QStringLiteral("json")));
    if (sub == QLatin1String("set"))
        return cmdSet(d, port, rest, p.isSet(QStringLiteral("save")), p.isSet(QStringLiteral("reboot")),
                      p.isSet(QStringLiteral("dry-run")));
    if (sub == QLatin1String("diff"))
        return cmdDiff(d, rest.front(), p.isSet(QStringLiteral("json")));
    if (sub == QLatin1String("export")) {
        const auto profile = settings::ConfigProfile::fromConfiguration(d.controller.configuration());
        if (!profile.save(rest.front(), &error))
            return fail(error);
        out(QStringLiteral("saved %1 settings to %2").arg(profile.settings.size()).arg(rest.front()));
        return ExitOk;
    }
    // action NAME[=ARG]
    const QString a = rest.front();
    const qsizetype eq = a.indexOf(QLatin1Char('='));
    QString name = eq > 0 ? a.left(eq) : a;
    QString arg = eq > 0 ? a.mid(eq + 1) : QString();
    if (name.compare(QLatin1String("ATT.RST"), Qt::CaseInsensitive) == 0) { // ATT.RST=3 is ATT.RST.3
        name = QStringLiteral("ATT.RST.") + arg;
        arg.clear();
    }
    const auto *def = SettingCatalog::findAction(name);
    if (!def)
        return fail(QStringLiteral("unknown action '%1' (ATT.RST.1/2/3/5, YAW, SAVECONFIG, REBOOT, FRESET)").arg(name),
                    ExitUsage);
    out(QStringLiteral("# %1").arg(SettingCatalog::conditions(*def)));
    QString detail;
    if (!runAction(d, name, arg, &detail))
        return fail(QStringLiteral("%1: %2").arg(name, detail));
    out(QStringLiteral("%1 OK").arg(QLatin1String(def->key)));
    return ExitOk;
}

} // namespace imudesk::cli
