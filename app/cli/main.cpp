// imudesk-cli: the headless composition root. Each command is one function over core.
#include "cli_context.h"

#include <QCoreApplication>
#include <QGuiApplication>
#include <QLoggingCategory>

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <map>
#include <memory>
#include <vector>

using namespace imudesk::cli;

namespace {
void usage(FILE *to)
{
    std::fputs("usage: imudesk-cli COMMAND [options]\n"
               "  ports [--json]                         list serial ports\n"
               "  probe PORT [--baud B] [--json]         detect baud rate and identity\n"
               "  discover [--ports P1,P2] [--can PLUGIN:IF,...] [--only-listed] [--timeout S] [--json]\n"
               "                                         one sweep finds every device: serial ports and rates, Modbus\n"
               "                                         ids, CAN bit rates and nodes; exit 0 found, 1 conflict, 2 none\n"
               "  read PORT [--baud B] [--duration S | --once TYPE] [--json]\n"
               "                                         print decoded samples\n"
               "  send PORT [--baud B] \"COMMAND\"         send an ASCII command, print the reply\n"
               "  decode FILE [--json]                   decode a raw capture\n"
               "  config PORT [set KEY=VALUE...|action NAME|export F|diff F|apply F] [--save] [--reboot] [--json]\n"
               "                                         read, set, compare and apply device settings\n"
               "  record PORT -o FILE [--duration S] [--baud B]  record what the device sends to a capture file\n"
               "  record PORT,PORT[,...] -o FOLDER|FILE.mcap [--duration S]  several devices: a session, or one MCAP\n"
               "  align FOLDER [--reference NAME] [--from S --to S] [--dry-run]\n"
               "                                         twist-to-align: the devices' offsets from a fixture's sharp turns\n"
               "  export FILE --format vendor-csv|csv|jsonl|mcap|mat [-o OUT] [--from S --to S]\n"
               "                                         export a capture (or a time range of it)\n"
               "  export FOLDER --format csv|jsonl|mcap|mat [-o OUT] [--grid-ms MS]  a session, its devices aligned\n"
               "  import CSV [-o OUT.imucap]             turn a vendor HI91 CSV into a capture\n"
               "  repair FILE.mcap [-o OUT]              complete an MCAP recording that was not closed (killed)\n"
               "  bridge PORT[,PORT...] [--listen ADDR:PORT] [--udp HOST:PORT] [--duration S]\n"
               "                                         stream the devices live to Foxglove, Lichtblick and\n"
               "                                         PlotJuggler (Foxglove WebSocket; PlotJuggler UDP JSON)\n"
               "  analyze FILE [--json]                  statistics, output rate, Allan deviation of a capture or\n"
               "                                         vendor CSV\n"
               "  magcal FILE [--json] [--mode full|hard_iron_only|planar] [--field UT]\n"
               "                                         magnetometer calibration of a CSV (mag_x,mag_y,mag_z uT)\n"
               "  verify CAPTURE|SESSION|PORT [--gravity M_S2 | --latitude DEG --height M] [--json]\n"
               "                                         is the module right? its accelerometer, gyro and attitude\n"
               "                                         judged from still poses; exit 0 pass, 1 fail or warn,\n"
               "                                         2 cannot judge\n"
               "  calibrate PORT mag|gyro-scale|level|heading-reset|hec495-clear [--json]\n"
               "                                         run a device-side calibration, progress on stderr\n"
               "  station PLAN.json PORT[,PORT...] [--report DIR] [--baud B] [--json] [--results URL]\n"
               "                                         run a production test plan on every module at once;\n"
               "                                         exit code 0 only when every module passed\n"
               "  results serial SN | yield --plan NAME | export --since DATE | upload | setup\n"
               "          [--db FILE | --results postgresql://...] [--json]\n"
               "                                         a results database: a module's history, a plan's yield,\n"
               "                                         records as CSV/JSONL, a station's upload, the line's schema\n"
               "  simulate --pty [--model HI14] [--firmware 1.7.1] [--baud 115200]\n"
               "           [--motion static|spin|tumble|turntable|twists|poses|bearings] [--seed N] [--faults LIST]\n"
               "                                         serve a simulated device on a pseudo-terminal; LIST:\n"
               "                                         noisy-gyro[=F],mounting=R/P/Y|wrong-mounting,\n"
               "                                         mag-disturbance[=U],unplug=T,fixture,acc-bias=X/Y/Z,\n"
               "                                         acc-scale=X/Y/Z,acc-error=MG/PCT,gyro-scale=PCT,\n"
               "                                         attitude-bias=R/P/H,filter-lag=MS\n"
               "  simulate --pty --modbus [--device hipnuc|hec495] [--id N] [--baud B]\n"
               "                                         serve a simulated Modbus RTU device\n"
               "  modbus PORT [--id N] [--baud B] info|read [REG [COUNT]]|scan|write REG VALUE [--json]\n"
               "                                         talk Modbus RTU to a module on RS-485\n"
               "  update PORT FILE [--baud B] [--json]   update the firmware (KBOOT), verified by read-back\n"
               "  update --can PLUGIN:IF [--node N] [--bitrate B] FILE [--json]   update over CANopen SDO (0x1F51)\n"
               "  simulate --pty --device hec495 [--baud 9600] [--address N] [--motion M] [--seed N]\n"
               "  hec495 PORT [--baud B] [--address N] [--json] read|angle A|nmea|info|declination [VALUE]|baud B|\n"
               "         rate HZ|content C|address N|save|reset|calibrate METHOD [--auto-interval S] [--save]\n"
               "                                         talk to a Witlink HEC495 compass\n"
               "  simulate --can virtualcan:can0 --protocol j1939|canopen [--device hipnuc|hec495] [--node N] [--fd]\n"
               "                                         serve a simulated CAN device\n"
               "  can [--plugin P] [--interface I] [--bitrate B] [--fd [--data-bitrate B]] [--protocol P] [--node N]\n"
               "      list|scan|read|get NAME|set NAME VALUE|config|reg|sdo|sync|output on|off|action NAME [--json]\n"
               "                                         CAN devices (J1939, CANopen, HEC495)\n"
               "Run 'imudesk-cli COMMAND --help' for a command's options.\n",
               to);
}

// Edits (insert, delete, replace, swap two neighbours) that turn a into b.
int editDistance(const QString &a, const QString &b)
{
    const qsizetype n = a.size(), m = b.size();
    std::vector<std::vector<int>> d(size_t(n + 1), std::vector<int>(size_t(m + 1)));
    for (qsizetype i = 0; i <= n; ++i)
        d[size_t(i)][0] = int(i);
    for (qsizetype j = 0; j <= m; ++j)
        d[0][size_t(j)] = int(j);
    for (qsizetype i = 1; i <= n; ++i)
        for (qsizetype j = 1; j <= m; ++j) {
            const int cost = a[i - 1] == b[j - 1] ? 0 : 1;
            int best = std::min({d[size_t(i - 1)][size_t(j)] + 1, d[size_t(i)][size_t(j - 1)] + 1,
                                 d[size_t(i - 1)][size_t(j - 1)] + cost});
            if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1])
                best = std::min(best, d[size_t(i - 2)][size_t(j - 2)] + 1);
            d[size_t(i)][size_t(j)] = best;
        }
    return d[size_t(n)][size_t(m)];
}

// The command a mistyped word most likely meant: the only one within two edits (one for a
// short word), or the only one it begins; empty when none is obvious.
QString closestCommand(const QString &word, const QStringList &commands)
{
    const QString typed = word.toLower();
    const int allowed = typed.size() <= 4 ? 1 : 2;
    QStringList closest, starts;
    int best = allowed + 1;
    for (const QString &c : commands) {
        const int d = editDistance(typed, c);
        if (d < best) {
            best = d;
            closest = QStringList{c};
        } else if (d == best) {
            closest << c;
        }
        if (typed.size() >= 3 && c.startsWith(typed))
            starts << c;
    }
    if (closest.size() == 1)
        return closest.front();
    if (closest.isEmpty() && starts.size() == 1)
        return starts.front();
    return {};
}
} // namespace

int main(int argc, char **argv)
{
    // The station writes PDF reports (QtGui): it gets a QGuiApplication on the offscreen
    // platform, so no display is needed; every other command stays a QCoreApplication.
    const bool station = argc > 1 && std::strcmp(argv[1], "station") == 0;
    if (station && qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM"))
        qputenv("QT_QPA_PLATFORM", "offscreen");
    std::unique_ptr<QCoreApplication> application = station ? std::make_unique<QGuiApplication>(argc, argv)
                                                            : std::make_unique<QCoreApplication>(argc, argv);
    QCoreApplication &app = *application;
    QCoreApplication::setApplicationName(QStringLiteral("imudesk-cli"));
    QCoreApplication::setApplicationVersion(QStringLiteral(IMUDESK_VERSION));
    installSignalHandlers();
    // stdout carries the results; keep informational logging off unless asked for (QT_LOGGING_RULES).
    if (qEnvironmentVariableIsEmpty("QT_LOGGING_RULES"))
        QLoggingCategory::setFilterRules(QStringLiteral("imudesk.*.info=false\nimudesk.*.debug=false"));
    const QStringList args = app.arguments();
    if (args.size() < 2) {
        usage(stderr);
        return ExitUsage;
    }
    const QString cmd = args.at(1);
    if (cmd == QLatin1String("--help") || cmd == QLatin1String("-h") || cmd == QLatin1String("help")) {
        usage(stdout);
        return ExitOk;
    }
    if (cmd == QLatin1String("--version")) {
        std::printf("imudesk-cli %s\n", IMUDESK_VERSION);
        return ExitOk;
    }
    static const std::map<QString, CommandFn> commands = {
        {QStringLiteral("ports"), cmdPorts},     {QStringLiteral("probe"), cmdProbe},
        {QStringLiteral("read"), cmdRead},       {QStringLiteral("send"), cmdSend},
        {QStringLiteral("decode"), cmdDecode},   {QStringLiteral("simulate"), cmdSimulate},
        {QStringLiteral("modbus"), cmdModbus},
        {QStringLiteral("config"), cmdConfig},
        {QStringLiteral("record"), cmdRecord},   {QStringLiteral("export"), cmdExport},
        {QStringLiteral("align"), cmdAlign},
        {QStringLiteral("analyze"), cmdAnalyze}, {QStringLiteral("import"), cmdImport},
        {QStringLiteral("repair"), cmdRepair},
        {QStringLiteral("bridge"), cmdBridge},
        {QStringLiteral("results"), cmdResults},
        {QStringLiteral("update"), cmdUpdate},
        {QStringLiteral("hec495"), cmdHec495},
        {QStringLiteral("can"), cmdCan},
        {QStringLiteral("magcal"), cmdMagcal},
        {QStringLiteral("calibrate"), cmdCalibrate},
        {QStringLiteral("station"), cmdStation},
        {QStringLiteral("verify"), cmdVerify},
        {QStringLiteral("discover"), cmdDiscover},
    };
    const auto it = commands.find(cmd);
    if (it == commands.end()) {
        // One line that names the word (and what it probably meant), not the whole usage: the
        // mistake stays on screen.
        QStringList names;
        for (const auto &entry : commands)
            names << entry.first;
        const QString closest = closestCommand(cmd, names);
        fail(closest.isEmpty() ? QStringLiteral("unknown command '%1'").arg(cmd)
                               : QStringLiteral("unknown command '%1'; did you mean '%2'?").arg(cmd, closest),
             ExitUsage);
        std::fputs("Run 'imudesk-cli --help' for the list of commands.\n", stderr);
        return ExitUsage;
    }
    // The sub-parser sees "imudesk-cli <cmd> args..." so its positional arguments start after the command.
    QStringList sub = args.mid(1);
    sub[0] = args.at(0) + QLatin1Char(' ') + cmd;
    return it->second(sub);
}
