// imudesk-cli modbus PORT [--id N] [--baud B] [--parity P] [--device hipnuc|hec495] info|read|scan|write ...
// and the Modbus side of `simulate --pty --modbus`.
#include "cli_context.h"

#include "device/modbus_session.h"
#include "format/sample_json.h"
#include "protocol/modbus/hipnuc_writes.h"
#include "protocol/modbus/register_block.h"
#include "protocol/modbus/register_decoder.h"
#include "protocol/modbus/register_map.h"
#include "sim/modbus_simulator.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>

#include <cstdio>

namespace imudesk::cli {

namespace {

using device::ModbusOptions;
using device::ModbusRegisterReply;
using device::ModbusSession;
using protocol::modbus::DeviceKind;
using protocol::modbus::HipnucWrites;
using protocol::modbus::RegisterBlock;
using protocol::modbus::RegisterDef;
using protocol::modbus::RegisterMap;

const QString kUsage = QStringLiteral(
    "imudesk-cli modbus PORT [--id N] [--baud B] [--parity none|even|odd] [--device hipnuc|hec495] [--timeout MS] "
    "info | read [REG [COUNT]] | scan [--from N] [--to N] [--all-bauds] | write REG VALUE [--no-verify]  [--json]");

QString jsonLine(const QJsonObject &o)
{
    return QString::fromUtf8(QJsonDocument(o).toJson(QJsonDocument::Compact));
}

// "0x34", "52", or a register name of the map ("ACCX", "md_id").
bool parseRegister(const QString &text, const RegisterMap &map, int *address)
{
    bool ok = false;
    const int v = text.startsWith(QLatin1String("0x"), Qt::CaseInsensitive) ? text.mid(2).toInt(&ok, 16) : text.toInt(&ok);
    if (ok && v >= 0 && v <= 0xFFFF) {
        *address = v;
        return true;
    }
    if (const RegisterDef *d = map.findByName(text)) {
        *address = d->address;
        return true;
    }
    return false;
}

bool parseValue(const QString &text, int *value)
{
    bool ok = false;
    const int v = text.startsWith(QLatin1String("0x"), Qt::CaseInsensitive) ? text.mid(2).toInt(&ok, 16) : text.toInt(&ok);
    if (!ok || v < 0 || v > 0xFFFF)
        return false;
    *value = v;
    return true;
}

// Opens the session and waits for Connected (or the failure).
bool openSession(ModbusSession &session, const ModbusOptions &o, model::DeviceIdentity *identity, QString *error)
{
    bool done = false, ok = false;
    QString message;
    QObject ctx;
    QObject::connect(&session, &ModbusSession::identityChanged, &ctx, [identity](const model::DeviceIdentity &id) {
        if (identity)
            *identity = id;
    });
    QObject::connect(&session, &ModbusSession::stateChanged, &ctx, [&](device::SessionState s, const QString &detail) {
        if (s == device::SessionState::Connected) {
            ok = done = true;
        } else if (s == device::SessionState::Failed || s == device::SessionState::Disconnected) {
            message = detail;
            done = true;
        }
    });
    session.open(o);
    waitFor([&] { return done; }, o.timeoutMs * (o.retries + 1) + 5000);
    if (!ok && error)
        *error = interrupted() ? QStringLiteral("interrupted")
                               : (message.isEmpty() ? QStringLiteral("timed out opening %1").arg(o.port) : message);
    return ok;
}

bool waitReply(ModbusSession &session, bool write, quint64 id, ModbusRegisterReply *out)
{
    bool done = false;
    QObject ctx;
    auto take = [&](const ModbusRegisterReply &r) {
        if (r.id == id) {
            *out = r;
            done = true;
        }
    };
    if (write)
        QObject::connect(&session, &ModbusSession::writeFinished, &ctx, take);
    else
        QObject::connect(&session, &ModbusSession::registersRead, &ctx, take);
    waitFor([&] { return done; }, 30000);
    return done;
}

int runInfo(ModbusSession &session, const ModbusOptions &o, const model::DeviceIdentity &id, bool json)
{
    QJsonObject obj;
    obj[QStringLiteral("port")] = o.port;
    obj[QStringLiteral("node")] = o.effectiveNodeId();
    obj[QStringLiteral("baud")] = o.effectiveBaud();
    obj[QStringLiteral("product")] = QString::fromStdString(id.productName);
    obj[QStringLiteral("software")] = QString::fromStdString(id.build);
    obj[QStringLiteral("firmware")] = id.firmware ? QString::fromStdString(id.firmware->toString()) : QString();
    obj[QStringLiteral("bootloader")] = id.bootloader ? QString::fromStdString(id.bootloader->toString()) : QString();
    obj[QStringLiteral("serial")] = QString::fromStdString(id.serial);
    if (o.kind == DeviceKind::Hipnuc) {
        ModbusRegisterReply r;
        if (!waitReply(session, false, session.readRegisters(protocol::modbus::reg::kBaud, 3), &r) || !r.ok)
            return fail(r.message.isEmpty() ? QStringLiteral("no reply to the configuration read") : r.message);
        obj[QStringLiteral("uart1_baud")] = HipnucWrites::baudForCode(r.values.value(0)).value_or(0);
        obj[QStringLiteral("md_id")] = r.values.value(1);
        obj[QStringLiteral("heading_mode")] = r.values.value(2) ? QStringLiteral("9-axis") : QStringLiteral("6-axis");
    }
    if (json) {
        out(jsonLine(obj));
        return ExitOk;
    }
    for (auto it = obj.begin(); it != obj.end(); ++it)
        out(QStringLiteral("%1: %2").arg(it.key(), it.value().toVariant().toString()));
    return ExitOk;
}

int runRead(ModbusSession &session, const ModbusOptions &o, const QStringList &rest, bool json)
{
    const RegisterMap &map = RegisterMap::forDevice(o.kind);
    int start = o.kind == DeviceKind::Hec495 ? protocol::modbus::reg::kHecAngles : protocol::modbus::reg::kSensorStart;
    int count = o.kind == DeviceKind::Hec495 ? protocol::modbus::reg::kHecAngleCount : protocol::modbus::reg::kSensorCount;
    const bool raw = !rest.isEmpty();
    if (raw) {
        if (!parseRegister(rest.at(0), map, &start))
            return fail(QStringLiteral("'%1' is neither a register address nor a register name").arg(rest.at(0)), ExitUsage);
        const RegisterDef *d = map.find(uint16_t(start));
        count = d ? d->words : 1;
        if (rest.size() > 1 && (!parseValue(rest.at(1), &count) || count < 1 || count > 125))
            return fail(QStringLiteral("COUNT must be 1..125"), ExitUsage);
    }
    ModbusRegisterReply r;
    if (!waitReply(session, false, session.readRegisters(start, count), &r))
        return fail(QStringLiteral("no answer"), interrupted() ? ExitInterrupted : ExitFailure);
    if (!r.ok)
        return fail(r.message);
    const RegisterBlock block(uint16_t(start), std::vector<uint16_t>(r.values.begin(), r.values.end()));
    if (!raw) {
        model::Sample s = protocol::modbus::RegisterDecoder::sample(o.kind, block);
        if (json) {
            outRaw(format::sampleToJson(s));
        } else {
            out(QStringLiteral("acc [G]: %1 %2 %3").arg(s.acc.x).arg(s.acc.y).arg(s.acc.z));
            out(QStringLiteral("gyr [deg/s]: %1 %2 %3").arg(s.gyr.x).arg(s.gyr.y).arg(s.gyr.z));
            out(QStringLiteral("mag [uT]: %1 %2 %3").arg(s.mag.x).arg(s.mag.y).arg(s.mag.z));
            out(QStringLiteral("roll/pitch/yaw [deg]: %1 %2 %3").arg(s.roll).arg(s.pitch).arg(s.yaw));
        }
        return ExitOk;
    }
    QJsonArray regs;
    for (int i = 0; i < count; ++i) {
        const uint16_t a = uint16_t(start + i);
        const RegisterDef *d = map.find(a);
        QJsonObject e;
        e[QStringLiteral("address")] = a;
        e[QStringLiteral("raw")] = r.values.value(i);
        QString line = QStringLiteral("0x%1 %2").arg(a, 4, 16, QLatin1Char('0')).arg(r.values.value(i), 6);
        if (d) {
            const auto text = block.text(*d);
            e[QStringLiteral("name")] = QLatin1String(d->name);
            if (text)
                e[QStringLiteral("value")] = QString::fromStdString(*text);
            e[QStringLiteral("unit")] = QLatin1String(d->unit);
            line += QStringLiteral("  %1 = %2 %3").arg(QLatin1String(d->name), text ? QString::fromStdString(*text) : QStringLiteral("(incomplete)"),
                                                      QLatin1String(d->unit));
        }
        if (json)
            regs.append(e);
        else
            out(line.trimmed());
    }
    if (json)
        out(QString::fromUtf8(QJsonDocument(regs).toJson(QJsonDocument::Compact)));
    return ExitOk;
}

int runWrite(ModbusSession &session, const ModbusOptions &o, const QStringList &rest, bool verify, bool json)
{
    if (rest.size() != 2)
        return fail(QStringLiteral("write needs REG VALUE (usage: %1)").arg(kUsage), ExitUsage);
    const RegisterMap &map = RegisterMap::forDevice(o.kind);
    int address = 0, value = 0;
    if (!parseRegister(rest.at(0), map, &address))
        return fail(QStringLiteral("'%1' is neither a register address nor a register name").arg(rest.at(0)), ExitUsage);
    if (!parseValue(rest.at(1), &value))
        return fail(QStringLiteral("VALUE must be 0..65535 (decimal or 0x hex)"), ExitUsage);
    // UART1_BAUD also takes the rate itself ("write UART1_BAUD 9600").
    if (o.kind == DeviceKind::Hipnuc && address == protocol::modbus::reg::kBaud && value > 8)
        if (const auto code = HipnucWrites::codeForBaud(value))
            value = *code;
    ModbusRegisterReply r;
    if (!waitReply(session, true, session.writeRegister(address, value, verify), &r))
        return fail(QStringLiteral("no answer"), interrupted() ? ExitInterrupted : ExitFailure);
    if (json) {
        QJsonObject obj;
        obj[QStringLiteral("address")] = address;
        obj[QStringLiteral("value")] = value;
        obj[QStringLiteral("ok")] = r.ok;
        obj[QStringLiteral("message")] = r.message;
        out(jsonLine(obj));
    } else if (r.ok) {
        out(r.message);
    }
    return r.ok ? ExitOk : fail(r.message);
}

int runScan(ModbusSession &session, const QCommandLineParser &p, bool json)
{
    device::ModbusScanOptions s;
    bool ok1 = true, ok2 = true;
    if (p.isSet(QStringLiteral("from")))
        s.firstId = p.value(QStringLiteral("from")).toInt(&ok1);
    if (p.isSet(QStringLiteral("to")))
        s.lastId = p.value(QStringLiteral("to")).toInt(&ok2);
    if (!ok1 || !ok2 || s.firstId < 1 || s.lastId > 247 || s.firstId > s.lastId)
        return fail(QStringLiteral("--from/--to must be node IDs 1..247, from <= to"), ExitUsage);
    if (p.isSet(QStringLiteral("timeout")))
        s.timeoutMs = p.value(QStringLiteral("timeout")).toInt();
    if (p.isSet(QStringLiteral("all-bauds")))
        for (int b : HipnucWrites::bauds())
            s.bauds.append(b);
    bool done = false, cancelled = false;
    int found = 0;
    QObject ctx;
    QObject::connect(&session, &ModbusSession::scanFound, &ctx, [&](const device::ModbusScanHit &h) {
        ++found;
        if (json) {
            QJsonObject o;
            o[QStringLiteral("node")] = h.nodeId;
            o[QStringLiteral("baud")] = h.baud;
            o[QStringLiteral("identified")] = h.identified;
            o[QStringLiteral("product")] = QString::fromStdString(h.identity.productName);
            o[QStringLiteral("serial")] = QString::fromStdString(h.identity.serial);
            o[QStringLiteral("summary")] = h.summary;
            out(jsonLine(o));
        } else {
            out(QStringLiteral("node %1 at %2 baud: %3").arg(h.nodeId).arg(h.baud).arg(h.summary));
        }
    });
    QObject::connect(&session, &ModbusSession::scanProgress, &ctx, [&](int n, int total) {
        if (!json && (n % 16 == 0 || n == total)) {
            std::fprintf(stderr, "\rscanned %d/%d", n, total);
            std::fflush(stderr);
        }
    });
    QObject::connect(&session, &ModbusSession::scanFinished, &ctx, [&](const QList<device::ModbusScanHit> &, bool c) {
        cancelled = c;
        done = true;
    });
    session.scan(s);
    waitFor([&] { return done; }, -1);
    if (!done) { // interrupted
        session.cancelScan();
        waitFor([&] { return done; }, 5000);
    }
    if (!json)
        std::fputc('\n', stderr);
    if (interrupted())
        return ExitInterrupted;
    if (found == 0)
        return fail(QStringLiteral("no device answered (IDs %1-%2). Check the wiring, baud and parity, or try --all-bauds")
                        .arg(s.firstId)
                        .arg(s.lastId));
    return cancelled ? ExitFailure : ExitOk;
}

} // namespace

int cmdModbus(const QStringList &args)
{
    QCommandLineParser p;
    p.addOption(QCommandLineOption(QStringLiteral("id"), QStringLiteral("Node ID (default 80 HiPNUC, 1 HEC495)."), QStringLiteral("N")));
    p.addOption(QCommandLineOption(QStringLiteral("baud"), QStringLiteral("Baud rate (default 115200 HiPNUC, 9600 HEC495)."),
                                   QStringLiteral("B")));
    p.addOption(QCommandLineOption(QStringLiteral("parity"), QStringLiteral("none (default), even or odd."), QStringLiteral("P"),
                                   QStringLiteral("none")));
    p.addOption(QCommandLineOption(QStringLiteral("device"), QStringLiteral("hipnuc (default) or hec495."), QStringLiteral("KIND"),
                                   QStringLiteral("hipnuc")));
    p.addOption(QCommandLineOption(QStringLiteral("timeout"), QStringLiteral("Reply timeout in ms (default 500; scan: per probe, default from the baud)."),
                                   QStringLiteral("MS"), QStringLiteral("500")));
    p.addOption(QCommandLineOption(QStringLiteral("from"), QStringLiteral("scan: first node ID (default 1)."), QStringLiteral("N")));
    p.addOption(QCommandLineOption(QStringLiteral("to"), QStringLiteral("scan: last node ID (default 247)."), QStringLiteral("N")));
    p.addOption(QCommandLineOption(QStringLiteral("all-bauds"), QStringLiteral("scan: every baud of the module's table.")));
    p.addOption(QCommandLineOption(QStringLiteral("no-verify"), QStringLiteral("write: do not read the register back.")));
    p.addOption(QCommandLineOption(QStringLiteral("json"), QStringLiteral("JSON output.")));
    p.addPositionalArgument(QStringLiteral("PORT"), QStringLiteral("Serial port of the RS-485 adapter"));
    p.addPositionalArgument(QStringLiteral("ACTION"), QStringLiteral("info, read, scan or write"));
    if (!parseArgs(p, args, kUsage))
        return ExitUsage;
    const QStringList pos = p.positionalArguments();
    if (pos.size() < 2)
        return fail(QStringLiteral("modbus needs PORT and an action (usage: %1)").arg(kUsage), ExitUsage);
    ModbusOptions o;
    o.port = pos.at(0);
    const QString action = pos.at(1);
    const QString kind = p.value(QStringLiteral("device")).toLower();
    if (kind == QLatin1String("hec495"))
        o.kind = DeviceKind::Hec495;
    else if (kind != QLatin1String("hipnuc"))
        return fail(QStringLiteral("--device must be hipnuc or hec495"), ExitUsage);
    bool ok = true;
    if (p.isSet(QStringLiteral("id"))) {
        o.nodeId = p.value(QStringLiteral("id")).toInt(&ok);
        if (!ok || o.nodeId < 1 || o.nodeId > 247)
            return fail(QStringLiteral("--id must be a node ID 1..247"), ExitUsage);
    }
    if (p.isSet(QStringLiteral("baud"))) {
        o.baud = p.value(QStringLiteral("baud")).toInt(&ok);
        if (!ok || o.baud < 1200 || o.baud > 4000000)
            return fail(QStringLiteral("--baud must be a rate such as 9600 or 115200"), ExitUsage);
    }
    const QString parity = p.value(QStringLiteral("parity")).toLower();
    if (parity == QLatin1String("even"))
        o.parity = QSerialPort::EvenParity;
    else if (parity == QLatin1String("odd"))
        o.parity = QSerialPort::OddParity;
    else if (parity != QLatin1String("none"))
        return fail(QStringLiteral("--parity must be none, even or odd"), ExitUsage);
    o.timeoutMs = p.value(QStringLiteral("timeout")).toInt(&ok);
    if (!ok || o.timeoutMs < 10 || o.timeoutMs > 60000)
        return fail(QStringLiteral("--timeout must be 10..60000 ms"), ExitUsage);
    o.pollHz = 0;
    o.identify = action != QLatin1String("scan");
    const bool json = p.isSet(QStringLiteral("json"));
    const QStringList rest = pos.mid(2);
    if (action != QLatin1String("info") && action != QLatin1String("read") && action != QLatin1String("scan")
        && action != QLatin1String("write"))
        return fail(QStringLiteral("unknown action '%1' (usage: %2)").arg(action, kUsage), ExitUsage);
    if ((action == QLatin1String("info") || action == QLatin1String("scan")) && !rest.isEmpty())
        return fail(QStringLiteral("%1 takes no arguments").arg(action), ExitUsage);
    if (action == QLatin1String("write") && rest.size() != 2)
        return fail(QStringLiteral("write needs REG VALUE (usage: %1)").arg(kUsage), ExitUsage);
    if (action == QLatin1String("read") && rest.size() > 2)
        return fail(QStringLiteral("read takes at most REG COUNT (usage: %1)").arg(kUsage), ExitUsage);

    ModbusSession session;
    model::DeviceIdentity id;
    QString error;
    if (!openSession(session, o, &id, &error))
        return fail(error, interrupted() ? ExitInterrupted : ExitFailure);
    if (action == QLatin1String("info"))
        return runInfo(session, o, id, json);
    if (action == QLatin1String("read"))
        return runRead(session, o, rest, json);
    if (action == QLatin1String("write"))
        return runWrite(session, o, rest, !p.isSet(QStringLiteral("no-verify")), json);
    return runScan(session, p, json);
}

void addModbusSimulateOptions(QCommandLineParser &p)
{
    p.addOption(QCommandLineOption(QStringLiteral("modbus"), QStringLiteral("Answer Modbus RTU instead of the serial protocol.")));
    p.addOption(QCommandLineOption(QStringLiteral("device"), QStringLiteral("With --modbus: hipnuc (default) or hec495."),
                                   QStringLiteral("KIND"), QStringLiteral("hipnuc")));
    p.addOption(QCommandLineOption(QStringLiteral("id"), QStringLiteral("With --modbus: node ID (default 80 HiPNUC, 1 HEC495)."),
                                   QStringLiteral("N")));
}

int simulateModbus(const QCommandLineParser &p)
{
    sim::ModbusSimOptions o;
    const QString kind = p.value(QStringLiteral("device")).toLower();
    if (kind == QLatin1String("hec495"))
        o.kind = DeviceKind::Hec495;
    else if (kind != QLatin1String("hipnuc"))
        return fail(QStringLiteral("--device must be hipnuc or hec495"), ExitUsage);
    bool ok = true;
    o.model = p.value(QStringLiteral("model")).toStdString();
    o.firmware = p.value(QStringLiteral("firmware")).toStdString();
    if (!model::FirmwareVersion::parse(o.firmware))
        return fail(QStringLiteral("--firmware must be a version such as 1.7.1 or 1.6.6"), ExitUsage);
    if (p.isSet(QStringLiteral("id"))) {
        o.nodeId = p.value(QStringLiteral("id")).toInt(&ok);
        if (!ok || o.nodeId < 1 || o.nodeId > 247)
            return fail(QStringLiteral("--id must be a node ID 1..247"), ExitUsage);
    }
    if (p.isSet(QStringLiteral("baud"))) {
        o.baud = p.value(QStringLiteral("baud")).toInt(&ok);
        if (!ok || !HipnucWrites::codeForBaud(o.baud))
            return fail(QStringLiteral("--baud must be one of 4800 9600 19200 38400 57600 115200 230400 460800 921600"),
                        ExitUsage);
    }
    if (!sim::parseMotion(p.value(QStringLiteral("motion")).toStdString(), o.motion))
        return fail(QStringLiteral("--motion must be static, spin or tumble"), ExitUsage);
    o.seed = p.value(QStringLiteral("seed")).toULongLong(&ok);
    if (!ok)
        return fail(QStringLiteral("--seed needs a whole number"), ExitUsage);
    sim::ModbusSimulator simulator(o);
    QString error;
    if (!simulator.start(&error))
        return fail(QStringLiteral("could not serve the simulated Modbus device: %1").arg(error));
    out(QStringLiteral("pty: %1").arg(simulator.devicePath()));
    out(QStringLiteral("modbus: node %1, %2 baud, 8N1").arg(simulator.nodeId()).arg(simulator.baud()));
    waitFor([] { return false; }, -1); // until SIGINT/SIGTERM
    simulator.stop();
    return ExitOk;
}

} // namespace imudesk::cli
