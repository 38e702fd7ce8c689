// imudesk-cli can ...: CAN devices through Qt SerialBus (list, scan, read, reg, sdo, sync).
#include "cli_context.h"

#include "device/can_session.h"
#include "format/sample_json.h"
#include "format/time_text.h"
#include "protocol/can/j1939.h"
#include "protocol/can/can_setting_catalog.h"
#include "sim/can_simulator.h"

#include <QCanBus>
#include <QCommandLineParser>
#include <QLoggingCategory>
#include <QMap>

#include <algorithm>
#include <cstdio>
#include <optional>

namespace imudesk::cli {

using device::CanSession;
using device::CanSessionOptions;
using protocol::can::CanProtocol;

namespace {

const char *kUsage = "imudesk-cli can [--plugin P] [--interface I] [--bitrate B] [--fd [--data-bitrate B]] "
                     "[--protocol auto|j1939|canopen|hec495] [--node N] [--extended] [--timeout MS] [--json] "
                     "list|scan|read|get|set|config|reg|sdo|sync|output|action ...\n"
                     "  list                                 plugins and their interfaces\n"
                     "  scan [--duration S] [--active]       nodes heard (and, with --active, an SDO scan of 1..127)\n"
                     "  read [--duration S]                  decoded samples\n"
                     "  reg read ADDR | reg write ADDR VALUE J1939 configuration register (--node 255: every node answers)\n"
                     "  sdo read INDEX SUB | sdo write INDEX SUB VALUE [--size 1..4]\n"
                     "  sync [PGN] [--count N] [--interval MS]  CANopen SYNC frames, or a J1939 one-shot PGN trigger\n"
                     "                                       (each confirmed by that PGN arriving; exit 1 when one is not)\n"
                     "  get NAME                             a setting as the module holds it (config lists the names)\n"
                     "  set NAME VALUE                       write a setting and read it back (bit rates in bit/s, e.g. 250000 or 250k)\n"
                     "  config                               every setting: name, value on the module, unit, range, note\n"
                     "  output on|off [--all]                the node's output (--all: NMT to every node)\n"
                     "  action save|reset|factory|heading-reset|zero|auto-level|clear-zero\n"
                     "                                       J1939 0x00 / 0xA5, CANopen 0x2000 / 0x20A5\n"
                     "  --extended                           HEC495: the extended-frame variant (0x18FA....)\n"
                     "  --source-address SA                  J1939: the host's source address (default 0x55, 0..253)";

// Qt's CAN plugins log their connection chatter at info level; the CLI's stderr is for errors.
void quietCanLogging()
{
    if (qEnvironmentVariableIsEmpty("QT_LOGGING_RULES"))
        QLoggingCategory::setFilterRules(QStringLiteral("imudesk.*.info=false\nimudesk.*.debug=false\n"
                                                        "qt.canbus.*.info=false\nqt.canbus.*.debug=false\nqt.canbus.*.warning=false"));
}

bool parseNumber(const QString &text, uint32_t *out)
{
    bool ok = false;
    const qulonglong v = text.startsWith(QLatin1String("0x"), Qt::CaseInsensitive) ? text.mid(2).toULongLong(&ok, 16)
                                                                                    : text.toULongLong(&ok, 10);
    if (!ok || v > 0xFFFFFFFFull)
        return false;
    *out = uint32_t(v);
    return true;
}

QString jsonString(const QString &s)
{
    QString o = s;
    o.replace(QLatin1Char('\\'), QStringLiteral("\\\\")).replace(QLatin1Char('"'), QStringLiteral("\\\""));
    return QLatin1Char('"') + o + QLatin1Char('"');
}

int cmdCanList(bool json, const QString &onlyPlugin)
{
    QStringList plugins = QCanBus::instance()->plugins();
    if (!onlyPlugin.isEmpty())
        plugins = QStringList{onlyPlugin};
    for (const QString &p : plugins) {
        QString error;
        const QStringList ifaces = CanSession::interfaces(p, &error);
        if (json) {
            QStringList quoted;
            for (const auto &i : ifaces)
                quoted << jsonString(i);
            out(QStringLiteral("{\"plugin\":%1,\"interfaces\":[%2]%3}")
                    .arg(jsonString(p), quoted.join(QLatin1Char(',')),
                         error.isEmpty() ? QString() : QStringLiteral(",\"error\":") + jsonString(error)));
        } else {
            out(QStringLiteral("%1: %2%3").arg(p, ifaces.isEmpty() ? QStringLiteral("(no interfaces)") : ifaces.join(QStringLiteral(" ")),
                                                error.isEmpty() ? QString() : QStringLiteral(" (%1)").arg(error)));
        }
    }
    return ExitOk;
}

bool openSession(CanSession &s, const CanSessionOptions &o, QString *error)
{
    s.open(o);
    QString detail;
    QObject::connect(&s, &CanSession::stateChanged, &s, [&](device::SessionState, const QString &d) { detail = d; });
    const bool done = waitFor([&] {
        const auto st = s.state();
        return st == device::SessionState::Connected || st == device::SessionState::Failed;
    }, 5000);
    if (done && s.state() == device::SessionState::Connected)
        return true;
    *error = done ? detail : QStringLiteral("the CAN interface %1:%2 did not connect within 5 s").arg(o.plugin, o.interfaceName);
    return false;
}

// The result of request id; nullopt when none came within 30 s (or on Ctrl+C).
std::optional<device::CanRequestResult> waitResult(CanSession &s, quint64 id)
{
    std::optional<device::CanRequestResult> result;
    const auto c = QObject::connect(&s, &CanSession::requestFinished, &s, [&](const device::CanRequestResult &r) {
        if (r.id == id)
            result = r;
    });
    waitFor([&] { return result.has_value(); }, 30000);
    QObject::disconnect(c);
    return result;
}

// What stands for a result that did not come.
device::CanRequestResult noResult()
{
    device::CanRequestResult r;
    r.message = interrupted() ? QStringLiteral("interrupted") : QStringLiteral("no result within 30 s");
    return r;
}

// Runs one request and prints its outcome.
int runRequest(CanSession &s, quint64 id, bool json, const QString &label)
{
    const std::optional<device::CanRequestResult> result = waitResult(s, id);
    if (!result)
        return fail(interrupted() ? QStringLiteral("interrupted") : QStringLiteral("%1: no result").arg(label),
                    interrupted() ? ExitInterrupted : ExitFailure);
    if (!result->ok)
        return fail(result->message);
    if (!result->answers.isEmpty()) {
        // A J1939 request to every node (255): one line per node that answered.
        int refused = 0;
        for (const device::CanNodeAnswer &a : result->answers) {
            refused += a.ok ? 0 : 1;
            if (json)
                out(QStringLiteral("{\"request\":%1,\"node\":%2,\"ok\":%3,\"value\":%4,\"status\":%5}")
                        .arg(jsonString(label))
                        .arg(a.node)
                        .arg(a.ok ? QStringLiteral("true") : QStringLiteral("false"))
                        .arg(a.value)
                        .arg(a.status));
            else if (a.ok)
                out(QStringLiteral("%1 node %2: %3 (0x%4)").arg(label).arg(a.node).arg(a.value).arg(a.value, 0, 16));
            else
                out(QStringLiteral("%1 node %2: refused (status %3)").arg(label).arg(a.node).arg(a.status));
        }
        if (refused > 0)
            return fail(QStringLiteral("%1: %2 of %3 nodes refused").arg(label).arg(refused).arg(result->answers.size()));
        return ExitOk;
    }
    if (json)
        out(QStringLiteral("{\"request\":%1,\"ok\":true,\"value\":%2}").arg(jsonString(label)).arg(result->value));
    else
        out(QStringLiteral("%1: %2 (0x%3)").arg(label).arg(result->value).arg(result->value, 0, 16));
    return ExitOk;
}

QStringList settingNames(const std::vector<protocol::can::CanSetting> &all)
{
    QStringList names;
    for (const auto &s : all)
        names << s.name;
    return names;
}

// A setting's value as read: a value of several registers from all of them.
QString shownValue(const protocol::can::CanSetting &s, const device::CanRequestResult &read)
{
    if (s.words > 1)
        return s.showWords(std::vector<uint32_t>(read.values.begin(), read.values.end()));
    return s.show(read.value);
}

QString settingJson(const protocol::can::CanSetting &s, const device::CanRequestResult *read)
{
    QString o = QStringLiteral("{\"name\":%1,\"label\":%2,\"unit\":%3,\"range\":%4,\"writable\":%5")
                    .arg(jsonString(s.name), jsonString(s.label), jsonString(s.unit), jsonString(s.range()),
                         s.writable ? QStringLiteral("true") : QStringLiteral("false"));
    if (read && read->ok)
        o += QStringLiteral(",\"value\":%1,\"raw\":%2").arg(jsonString(shownValue(s, *read))).arg(read->value);
    else
        o += QStringLiteral(",\"value\":null,\"why\":%1").arg(jsonString(read ? read->message : s.note));
    if (!s.note.isEmpty())
        o += QStringLiteral(",\"note\":%1").arg(jsonString(s.note));
    return o + QLatin1Char('}');
}

// can get NAME | set NAME VALUE | config: the settings by the device's catalogue.
int typedSetting(CanSession &session, const QString &sub, const QStringList &pos, bool json)
{
    const std::vector<protocol::can::CanSetting> all = session.settingsCatalogue();
    auto find = [&](const QString &name) -> const protocol::can::CanSetting * {
        for (const auto &s : all)
            if (s.name.compare(name, Qt::CaseInsensitive) == 0)
                return &s;
        return nullptr;
    };
    if (sub == QLatin1String("config")) {
        if (pos.size() != 1)
            return fail(QStringLiteral("usage: can config [--json]"), ExitUsage);
        int unread = 0;
        for (const auto &s : all) {
            std::optional<device::CanRequestResult> r;
            if (s.readable)
                r = waitResult(session, session.readSetting(s)).value_or(noResult());
            unread += s.readable && !r->ok;
            if (json) {
                out(settingJson(s, r ? &*r : nullptr));
                continue;
            }
            const QString value = !s.readable ? QStringLiteral("(not readable)")
                                  : r->ok     ? shownValue(s, *r) + (s.unit.isEmpty() ? QString() : QLatin1Char(' ') + s.unit)
                                              : QStringLiteral("(no answer: %1)").arg(r->message);
            out(QStringLiteral("%1\t%2\t[%3]%4").arg(s.name, value, s.range(),
                                                     s.note.isEmpty() ? QString() : QStringLiteral("\t%1").arg(s.note)));
            if (interrupted())
                return ExitInterrupted;
        }
        return unread == 0 ? ExitOk : ExitFailure;
    }
    if (pos.size() < 2)
        return fail(QStringLiteral("usage: can get NAME | can set NAME VALUE; the names: %1")
                        .arg(settingNames(all).join(QStringLiteral(", "))),
                    ExitUsage);
    const protocol::can::CanSetting *s = find(pos[1]);
    if (!s)
        return fail(QStringLiteral("unknown setting '%1' for %2: %3")
                        .arg(pos[1], QString::fromLatin1(protocol::can::protocolName(session.protocol())),
                             settingNames(all).join(QStringLiteral(", "))),
                    ExitUsage);
    if (sub == QLatin1String("get")) {
        if (pos.size() != 2)
            return fail(QStringLiteral("usage: can get NAME"), ExitUsage);
        if (!s->readable)
            return fail(QStringLiteral("%1 cannot be read: %2").arg(s->name, s->note));
        const device::CanRequestResult r = waitResult(session, session.readSetting(*s)).value_or(noResult());
        if (json) {
            out(settingJson(*s, &r));
            return r.ok ? ExitOk : ExitFailure;
        }
        if (!r.ok)
            return fail(r.message);
        out(QStringLiteral("%1: %2%3").arg(s->name, shownValue(*s, r), s->unit.isEmpty() ? QString() : QLatin1Char(' ') + s->unit));
        return ExitOk;
    }
    if (pos.size() != 3)
        return fail(QStringLiteral("usage: can set NAME VALUE"), ExitUsage);
    QString why;
    const std::optional<uint32_t> raw = s->parse(pos[2], &why);
    if (!raw)
        return fail(why, ExitUsage);
    const device::CanRequestResult r = waitResult(session, session.writeSetting(*s, *raw)).value_or(noResult());
    if (json)
        out(QStringLiteral("{\"name\":%1,\"value\":%2,\"ok\":%3,\"message\":%4}")
                .arg(jsonString(s->name), jsonString(s->show(*raw)), r.ok ? QStringLiteral("true") : QStringLiteral("false"),
                     jsonString(r.message)));
    else if (r.ok)
        out(r.message);
    if (!r.ok)
        return json ? ExitFailure : fail(r.message);
    return ExitOk;
}

// One text line of a CAN sample: the fields its frames carried, no zeros for the others.
QString sampleLine(const model::Sample &s, int node)
{
    QString line = QStringLiteral("%1 node %2").arg(QString::fromStdString(s.source)).arg(node);
    const auto vec = [](const char *name, const model::Vec3 &v, int decimals, const char *unit) {
        return QStringLiteral(" %1=[%2 %3 %4] %5")
            .arg(QLatin1String(name))
            .arg(v.x, 0, 'f', decimals)
            .arg(v.y, 0, 'f', decimals)
            .arg(v.z, 0, 'f', decimals)
            .arg(QLatin1String(unit));
    };
    if (s.fields & model::FieldAcc)
        line += vec("acc", s.acc, 3, "G");
    if (s.fields & model::FieldGyr)
        line += vec("gyr", s.gyr, 2, "deg/s");
    if (s.fields & model::FieldMag)
        line += vec("mag", s.mag, 1, "uT");
    if (s.fields & model::FieldMagRelative)
        line += vec("mag", s.magRelative, 3, "(relative)");
    if (s.fields & model::FieldEuler)
        line += vec("rpy", model::Vec3{s.roll, s.pitch, s.yaw}, 2, "deg");
    if (s.fields & model::FieldInclination)
        line += QStringLiteral(" incl=[%1 %2] deg").arg(s.inclinationX, 0, 'f', 2).arg(s.inclinationY, 0, 'f', 2);
    if (s.fields & model::FieldTemperature)
        line += QStringLiteral(" temp=%1 C").arg(s.temperatureC, 0, 'f', 1);
    if (s.utcTimeOfDayS >= 0)
        line += QStringLiteral(" utc=") + format::timeOfDayText(s.utcTimeOfDayS, 3);
    return line;
}

} // namespace

int cmdCan(const QStringList &args)
{
    quietCanLogging();
    QCommandLineParser p;
    p.addOption(QCommandLineOption(QStringLiteral("plugin"), QStringLiteral("Qt CAN plugin (default virtualcan)."),
                                   QStringLiteral("P"), QStringLiteral("virtualcan")));
    p.addOption(QCommandLineOption(QStringLiteral("interface"), QStringLiteral("Interface (default can0)."),
                                   QStringLiteral("I"), QStringLiteral("can0")));
    p.addOption(QCommandLineOption(QStringLiteral("bitrate"), QStringLiteral("Bit rate to set (default: leave)."), QStringLiteral("B")));
    p.addOption(QCommandLineOption(QStringLiteral("fd"), QStringLiteral("CAN FD bus (the J1939 FF5A frame).")));
    p.addOption(QCommandLineOption(QStringLiteral("data-bitrate"),
                                   QStringLiteral("CAN FD data-phase bit rate (default 4000000, the manual's)."),
                                   QStringLiteral("B")));
    p.addOption(QCommandLineOption(QStringLiteral("protocol"), QStringLiteral("auto (default), j1939, canopen or hec495."),
                                   QStringLiteral("PROTO"), QStringLiteral("auto")));
    p.addOption(QCommandLineOption(QStringLiteral("node"),
                                   QStringLiteral("Node ID / J1939 address (default: first heard; J1939 reg: 255 = every node)."),
                                   QStringLiteral("N")));
    p.addOption(QCommandLineOption(QStringLiteral("source-address"),
                                   QStringLiteral("J1939: the host's source address in requests (default 0x55, 0..253)."),
                                   QStringLiteral("SA")));
    p.addOption(QCommandLineOption(QStringLiteral("duration"), QStringLiteral("Seconds (scan: 2, read: until Ctrl+C)."),
                                   QStringLiteral("S")));
    p.addOption(QCommandLineOption(QStringLiteral("active"), QStringLiteral("scan: also read 0x1000 from nodes 1..127 (SDO).")));
    p.addOption(QCommandLineOption(QStringLiteral("size"), QStringLiteral("sdo write: bytes 1..4 (default 4)."),
                                   QStringLiteral("N"), QStringLiteral("4")));
    p.addOption(QCommandLineOption(QStringLiteral("count"), QStringLiteral("sync: frames to send (default 1)."),
                                   QStringLiteral("N"), QStringLiteral("1")));
    p.addOption(QCommandLineOption(QStringLiteral("interval"), QStringLiteral("sync: ms between frames (default 10)."),
                                   QStringLiteral("MS"), QStringLiteral("10")));
    p.addOption(QCommandLineOption(QStringLiteral("timeout"),
                                   QStringLiteral("Reply timeout in ms for each request (default 1000; a slow gateway "
                                                  "or a loaded bus needs more)."),
                                   QStringLiteral("MS")));
    p.addOption(QCommandLineOption(QStringLiteral("json"), QStringLiteral("JSON Lines output.")));
    p.addOption(QCommandLineOption(QStringLiteral("all"), QStringLiteral("output: NMT start/stop to every node (node 0).")));
    p.addOption(QCommandLineOption(QStringLiteral("extended"),
                                   QStringLiteral("HEC495: the extended-frame variant (requests on 0x18FA0227).")));
    p.addPositionalArgument(QStringLiteral("SUBCOMMAND"),
                            QStringLiteral("list, scan, read, get, set, config, reg, sdo, sync, output or action"),
                            QStringLiteral("SUBCOMMAND [ARGUMENTS...]"));
    if (!parseArgs(p, args, QString::fromLatin1(kUsage)))
        return ExitUsage;
    const QStringList pos = p.positionalArguments();
    if (pos.isEmpty())
        return fail(QStringLiteral("can needs a subcommand (usage: %1)").arg(QString::fromLatin1(kUsage)), ExitUsage);
    const QString sub = pos.front();
    const bool json = p.isSet(QStringLiteral("json"));
    if (sub == QLatin1String("list"))
        return cmdCanList(json, p.isSet(QStringLiteral("plugin")) ? p.value(QStringLiteral("plugin")) : QString());

    CanSessionOptions o;
    o.plugin = p.value(QStringLiteral("plugin"));
    o.interfaceName = p.value(QStringLiteral("interface"));
    const auto proto = protocol::can::parseProtocol(p.value(QStringLiteral("protocol")));
    if (!proto)
        return fail(QStringLiteral("--protocol must be auto, j1939, canopen or hec495"), ExitUsage);
    o.protocol = *proto;
    o.hec495Extended = p.isSet(QStringLiteral("extended"));
    if (o.hec495Extended && o.protocol != CanProtocol::Hec495)
        return fail(QStringLiteral("--extended is the HEC495's variant: give --protocol hec495 too"), ExitUsage);
    uint32_t n = 0;
    if (p.isSet(QStringLiteral("bitrate"))) {
        if (!parseNumber(p.value(QStringLiteral("bitrate")), &n) || n == 0)
            return fail(QStringLiteral("--bitrate needs a positive number"), ExitUsage);
        o.bitrate = int(n);
        // The rates the protocol's manual lists (a bus at another rate never hears the module).
        const std::vector<int> rates = protocol::can::canBitrates(o.protocol, o.hec495Extended).rates;
        if (std::find(rates.begin(), rates.end(), o.bitrate) == rates.end()) {
            QStringList listed;
            for (int r : rates)
                listed << QString::number(r);
            return fail(QStringLiteral("--bitrate %1 is not a rate of %2 (%3)")
                            .arg(o.bitrate)
                            .arg(QString::fromLatin1(protocol::can::protocolName(o.protocol)), listed.join(QStringLiteral(", "))),
                        ExitUsage);
        }
    }
    o.canFd = p.isSet(QStringLiteral("fd"));
    if (p.isSet(QStringLiteral("data-bitrate"))) {
        if (!o.canFd)
            return fail(QStringLiteral("--data-bitrate is the CAN FD data phase: give --fd too"), ExitUsage);
        if (!parseNumber(p.value(QStringLiteral("data-bitrate")), &n) || n == 0)
            return fail(QStringLiteral("--data-bitrate needs a positive number"), ExitUsage);
        o.dataBitrate = int(n);
    } else if (o.canFd) {
        o.dataBitrate = 4000000; // v1.7.1 7.19.30: "usually 4 Mbps"
    }
    if (p.isSet(QStringLiteral("timeout"))) {
        if (!parseNumber(p.value(QStringLiteral("timeout")), &n) || n < 50 || n > 600000)
            return fail(QStringLiteral("--timeout needs milliseconds, 50..600000"), ExitUsage);
        o.requestTimeoutMs = int(n);
    }
    if (p.isSet(QStringLiteral("node"))) {
        const bool broadcastOk = sub == QLatin1String("reg") && o.protocol != CanProtocol::CanOpen && o.protocol != CanProtocol::Hec495;
        if (!parseNumber(p.value(QStringLiteral("node")), &n) || (n > 253 && !(n == protocol::can::j1939::kBroadcast && broadcastOk)))
            return fail(QStringLiteral("--node needs 0..253 (255, every node, for J1939 reg read/write)"), ExitUsage);
        o.node = int(n);
    }
    if (p.isSet(QStringLiteral("source-address"))) {
        if (o.protocol != CanProtocol::J1939 && !(sub == QLatin1String("reg") && o.protocol == CanProtocol::Auto))
            return fail(QStringLiteral("--source-address is J1939's: give --protocol j1939 too"), ExitUsage);
        if (!parseNumber(p.value(QStringLiteral("source-address")), &n) || n > 253)
            return fail(QStringLiteral("--source-address needs 0..253 (254 is J1939's null address, 255 every node)"), ExitUsage);
        if (o.node >= 0 && int(n) == o.node)
            return fail(QStringLiteral("--source-address must differ from the module's address %1").arg(o.node), ExitUsage);
        o.hostAddress = uint8_t(n);
    }
    double duration = -1;
    if (p.isSet(QStringLiteral("duration"))) {
        bool ok = false;
        duration = p.value(QStringLiteral("duration")).toDouble(&ok);
        if (!ok || duration <= 0)
            return fail(QStringLiteral("--duration needs a positive number of seconds"), ExitUsage);
    }
    // Requests need a known protocol: without --protocol, listen until traffic shows it.
    const bool typed = sub == QLatin1String("get") || sub == QLatin1String("set") || sub == QLatin1String("config");
    // What only a named protocol can do (the raw reg, sdo and sync pick theirs below).
    const bool protocolOnly = typed || sub == QLatin1String("output") || sub == QLatin1String("action");
    const bool needsProtocol = sub == QLatin1String("reg") || sub == QLatin1String("sdo") || sub == QLatin1String("sync")
                            || protocolOnly;
    if (protocolOnly && o.protocol == CanProtocol::Auto)
        return fail(QStringLiteral("'%1' needs --protocol j1939, canopen or hec495").arg(sub), ExitUsage);
    if (sub == QLatin1String("reg") && o.protocol == CanProtocol::Auto)
        o.protocol = CanProtocol::J1939;
    if (sub == QLatin1String("sdo") && o.protocol == CanProtocol::Auto)
        o.protocol = CanProtocol::CanOpen;
    if (needsProtocol && o.node < 0)
        o.node = o.protocol == CanProtocol::Hec495 ? 5 : 8;

    CanSession session;
    if (sub == QLatin1String("scan")) // before opening: the first frames already discover nodes
        QObject::connect(&session, &CanSession::nodeDiscovered, &session, [json](const device::CanNodeInfo &i) {
            const QString proto = QString::fromLatin1(protocol::can::protocolName(i.protocol));
            if (json)
                out(QStringLiteral("{\"node\":%1,\"protocol\":%2,\"seen_as\":%3}").arg(i.node).arg(jsonString(proto), jsonString(i.seenAs)));
            else
                out(QStringLiteral("node %1 (%2, %3)").arg(i.node).arg(proto, i.seenAs));
        });
    QString error;
    if (!openSession(session, o, &error))
        return fail(error);

    if (sub == QLatin1String("scan")) {
        bool scanDone = !p.isSet(QStringLiteral("active"));
        QObject::connect(&session, &CanSession::scanFinished, &session, [&](const QList<int> &nodes, bool) {
            scanDone = true;
            QStringList ids;
            for (int n : nodes)
                ids << QString::number(n);
            if (json)
                out(QStringLiteral("{\"sdo_scan\":[%1]}").arg(ids.join(QLatin1Char(','))));
            else
                out(QStringLiteral("SDO scan 1..127: %1").arg(ids.isEmpty() ? QStringLiteral("no answer") : ids.join(QLatin1Char(' '))));
        });
        if (!scanDone)
            session.scanNodes(1, 127);
        const int ms = duration > 0 ? int(duration * 1000) : 2000;
        waitFor([] { return false; }, ms);
        waitFor([&] { return scanDone; }, 5000);
        return interrupted() ? ExitInterrupted : ExitOk;
    }
    if (sub == QLatin1String("read")) {
        uint64_t seq = 0, printed = 0;
        int64_t lastTextNs = 0;
        qint64 framesIn = 0, fdFramesIn = 0;
        QObject::connect(&session, &device::CanSession::framesSeen, &session, [&](const device::CanFrameEvents &events) {
            for (const auto &e : events) {
                if (e.transmitted)
                    continue;
                ++framesIn;
                fdFramesIn += e.frame.fd;
            }
        });
        auto drain = [&] {
            for (const auto &s : session.store().since(seq, SIZE_MAX, &seq)) {
                ++printed;
                if (json) {
                    outRaw(format::sampleToJson(s));
                } else if (s.hostTimeNs - lastTextNs >= 100'000'000) {
                    lastTextNs = s.hostTimeNs;
                    out(sampleLine(s, session.targetNode()));
                }
            }
            std::fflush(stdout);
            return false;
        };
        waitFor(drain, duration > 0 ? int(duration * 1000) : -1);
        drain();
        if (!json)
            out(QStringLiteral("samples: %1, protocol: %2, frames received: %3 (CAN FD: %4)")
                    .arg(printed)
                    .arg(QString::fromLatin1(protocol::can::protocolName(session.protocol())))
                    .arg(framesIn)
                    .arg(fdFramesIn));
        return interrupted() ? ExitInterrupted : ExitOk;
    }
    if (sub == QLatin1String("reg")) {
        uint32_t addr = 0, value = 0;
        if (pos.size() == 3 && pos[1] == QLatin1String("read") && parseNumber(pos[2], &addr) && addr <= 0xFFFF)
            return runRequest(session, session.readRegister(uint16_t(addr)), json, QStringLiteral("register 0x%1").arg(addr, 4, 16, QLatin1Char('0')));
        if (pos.size() == 4 && pos[1] == QLatin1String("write") && parseNumber(pos[2], &addr) && addr <= 0xFFFF && parseNumber(pos[3], &value))
            return runRequest(session, session.writeRegister(uint16_t(addr), value), json, QStringLiteral("register 0x%1").arg(addr, 4, 16, QLatin1Char('0')));
        return fail(QStringLiteral("usage: can reg read ADDR | can reg write ADDR VALUE (numbers decimal or 0x hex)"), ExitUsage);
    }
    if (sub == QLatin1String("sdo")) {
        uint32_t index = 0, subIndex = 0, value = 0, size = 4;
        const bool idxOk = pos.size() >= 4 && parseNumber(pos[2], &index) && index <= 0xFFFF && parseNumber(pos[3], &subIndex) && subIndex <= 0xFF;
        const QString label = QStringLiteral("0x%1.%2").arg(index, 4, 16, QLatin1Char('0')).arg(subIndex, 2, 16, QLatin1Char('0'));
        if (idxOk && pos.size() == 4 && pos[1] == QLatin1String("read"))
            return runRequest(session, session.sdoRead(uint16_t(index), uint8_t(subIndex)), json, label);
        if (idxOk && pos.size() == 5 && pos[1] == QLatin1String("write") && parseNumber(pos[4], &value)
            && parseNumber(p.value(QStringLiteral("size")), &size) && size >= 1 && size <= 4) {
            if (o.protocol == CanProtocol::Hec495)
                return runRequest(session, session.hec495Write(uint16_t(index), uint8_t(value)), json, label);
            return runRequest(session, session.sdoWrite(uint16_t(index), uint8_t(subIndex), value, int(size)), json, label);
        }
        return fail(QStringLiteral("usage: can sdo read INDEX SUB | can sdo write INDEX SUB VALUE [--size 1..4]"), ExitUsage);
    }
    if (sub == QLatin1String("sync")) {
        uint32_t count = 0, interval = 0, pgn = 0;
        if (!parseNumber(p.value(QStringLiteral("count")), &count) || count == 0 || !parseNumber(p.value(QStringLiteral("interval")), &interval))
            return fail(QStringLiteral("--count and --interval need whole numbers"), ExitUsage);
        const bool trigger = o.protocol == CanProtocol::J1939;
        if (trigger && (pos.size() != 2 || !parseNumber(pos[1], &pgn) || !protocol::can::j1939::isDataPgn(pgn)))
            return fail(QStringLiteral("J1939 sync needs a data PGN, e.g. can --protocol j1939 sync 0xFF34"), ExitUsage);
        uint32_t sent = 0, confirmed = 0;
        uint64_t received = 0;
        QString unconfirmed; // the first trigger the module did not answer, and why
        QObject::connect(&session, &CanSession::framesSeen, &session, [&](const device::CanFrameEvents &ev) {
            for (const auto &e : ev)
                received += e.transmitted ? 0 : 1;
        });
        for (; sent < count && !interrupted(); ++sent) {
            if (trigger) {
                // Confirmed as the session and the CAN panel confirm it: the requested PGN
                // arriving from the module (v1.7.1 7.23: the request itself has no reply).
                const device::CanRequestResult r = waitResult(session, session.trigger(pgn)).value_or(noResult());
                if (r.ok)
                    ++confirmed;
                else if (unconfirmed.isEmpty())
                    unconfirmed = r.message;
            } else {
                session.sendSync();
            }
            waitFor([] { return false; }, int(interval));
        }
        waitFor([] { return false; }, 100);
        if (json && trigger)
            out(QStringLiteral("{\"sent\":%1,\"confirmed\":%2,\"frames_received\":%3}").arg(sent).arg(confirmed).arg(received));
        else if (json)
            out(QStringLiteral("{\"sent\":%1,\"frames_received\":%2}").arg(sent).arg(received));
        else if (trigger)
            out(QStringLiteral("triggers sent: %1, confirmed by PGN %2: %3, frames received meanwhile: %4")
                    .arg(sent)
                    .arg(QString::number(pgn, 16).toUpper())
                    .arg(confirmed)
                    .arg(received));
        else
            out(QStringLiteral("SYNC sent: %1, frames received meanwhile: %2").arg(sent).arg(received));
        if (interrupted())
            return ExitInterrupted;
        if (trigger && confirmed < sent)
            return fail(QStringLiteral("%1 of %2 triggers of PGN %3 were not answered by node %4: %5")
                            .arg(sent - confirmed)
                            .arg(sent)
                            .arg(QString::number(pgn, 16).toUpper())
                            .arg(session.targetNode())
                            .arg(unconfirmed));
        return ExitOk;
    }
    if (typed)
        return typedSetting(session, sub, pos, json);
    if (sub == QLatin1String("output")) {
        if (pos.size() != 2 || (pos[1] != QLatin1String("on") && pos[1] != QLatin1String("off")))
            return fail(QStringLiteral("usage: can output on|off [--all]"), ExitUsage);
        const bool on = pos[1] == QLatin1String("on");
        const bool all = p.isSet(QStringLiteral("all"));
        return runRequest(session, all ? session.setAllNodesOutput(on) : session.setOutputEnabled(on), json,
                          QStringLiteral("output %1%2").arg(pos[1], all ? QStringLiteral(", every node") : QString()));
    }
    if (sub == QLatin1String("action")) {
        // The module's commands by name: J1939 0x0000 / 0x00A5 (v1.7.1 7.23), CANopen 0x2000 /
        // 0x20A5 (8.28.44, 8.28.45.25); each confirmed by the module's reply, the session
        // refusing what the protocol does not have (heading reset and auto level on CANopen).
        static const QMap<QString, int> kResets = {{QStringLiteral("heading-reset"), 1}, {QStringLiteral("zero"), 2},
                                                   {QStringLiteral("auto-level"), 3}, {QStringLiteral("clear-zero"), 5}};
        const QString name = pos.value(1);
        if (pos.size() != 2)
            return fail(QStringLiteral("usage: can action save|reset|factory|heading-reset|zero|auto-level|clear-zero"),
                        ExitUsage);
        if (name == QLatin1String("save"))
            return runRequest(session, session.save(), json, QStringLiteral("save"));
        if (name == QLatin1String("reset"))
            return runRequest(session, session.reset(), json, QStringLiteral("reset"));
        if (name == QLatin1String("factory"))
            return runRequest(session, session.factoryReset(), json, QStringLiteral("factory defaults"));
        if (kResets.contains(name))
            return runRequest(session, session.attitudeReset(kResets.value(name)), json, name);
        return fail(QStringLiteral("unknown action '%1': save, reset, factory, heading-reset, zero, auto-level or "
                                   "clear-zero")
                        .arg(name),
                    ExitUsage);
    }
    return fail(QStringLiteral("unknown can subcommand '%1' (usage: %2)").arg(sub, QString::fromLatin1(kUsage)), ExitUsage);
}

int simulateCan(const QString &canSpec, const QString &protocolText, const QString &deviceKind, int node, sim::Motion motion,
                uint64_t seed, const QString &firmware, bool canFd, const QString &flashDump)
{
    quietCanLogging();
    QString error;
    int dumped = ExitOk;
    const int rc = sim::runCanSimulatorCommand(canSpec, protocolText, deviceKind, node, motion, seed, firmware, canFd, &error,
                                               [] { return interrupted(); },
                                               [&](sim::CanSimDevice &d) { dumped = writeCanFlashDump(d, flashDump); });
    if (rc != 0)
        return fail(error, rc);
    return dumped;
}

} // namespace imudesk::cli
