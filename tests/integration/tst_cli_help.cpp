// imudesk-cli COMMAND --help (issue 53 points 17b and 17c): every usage line names the command
// ("usage: imudesk-cli magcal FILE ...", not Qt's "Usage: /path/imudesk-cli [options] FILE"),
// the synopsis names every option the command takes, and `can` lists every subcommand it runs.
#include "../common/cli_run.h"
#include "../common/test_main.h"

#include <QRegularExpression>
#include <QTest>

namespace {

const QStringList kCommands = {
    QStringLiteral("ports"),   QStringLiteral("probe"),     QStringLiteral("read"),    QStringLiteral("send"),
    QStringLiteral("decode"),  QStringLiteral("simulate"),  QStringLiteral("modbus"),  QStringLiteral("config"),
    QStringLiteral("record"),  QStringLiteral("export"),    QStringLiteral("align"),   QStringLiteral("analyze"),
    QStringLiteral("import"),  QStringLiteral("repair"),    QStringLiteral("bridge"),  QStringLiteral("results"),
    QStringLiteral("update"),  QStringLiteral("hec495"),    QStringLiteral("can"),     QStringLiteral("magcal"),
    QStringLiteral("calibrate"), QStringLiteral("station"),
};

// What `can` runs (app/cli/commands_can.cpp).
const QStringList kCanSubcommands = {
    QStringLiteral("list"), QStringLiteral("scan"), QStringLiteral("read"), QStringLiteral("get"),
    QStringLiteral("set"),  QStringLiteral("config"), QStringLiteral("reg"), QStringLiteral("sdo"),
    QStringLiteral("sync"), QStringLiteral("output"), QStringLiteral("action"),
};

imudesk::test::CliResult help(const QString &command)
{
    return imudesk::test::runCli({command, QStringLiteral("--help")}, 30000);
}

// The part of the help before Qt's option list: the command's own synopsis.
QString synopsis(const QString &helpText)
{
    const qsizetype options = helpText.indexOf(QLatin1String("\nOptions:"));
    return options < 0 ? helpText : helpText.left(options);
}

} // namespace

class TstCliHelp : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void usageNamesTheCommand_data()
    {
        QTest::addColumn<QString>("command");
        for (const QString &c : kCommands)
            QTest::newRow(qPrintable(c)) << c;
    }
    void usageNamesTheCommand()
    {
        QFETCH(QString, command);
        const auto r = help(command);
        QVERIFY2(r.code == 0, qPrintable(r.err));
        const QString expected = QStringLiteral("usage: imudesk-cli ") + command + QLatin1Char(' ');
        QVERIFY2(r.out.startsWith(expected), qPrintable(r.out.left(200)));
        for (const QString &line : r.out.split(QLatin1Char('\n'))) {
            const QString trimmed = line.trimmed();
            if (trimmed.startsWith(QLatin1String("usage:"), Qt::CaseInsensitive))
                QVERIFY2(trimmed.startsWith(expected), qPrintable(line));
            // A continued usage ("       imudesk-cli results yield ...") names the command too.
            if (trimmed.startsWith(QLatin1String("imudesk-cli ")))
                QVERIFY2(trimmed.startsWith(QStringLiteral("imudesk-cli ") + command), qPrintable(line));
        }
        // The program's path is not a usage: nothing names the executable by its path.
        QVERIFY2(!r.out.contains(QLatin1String("/imudesk-cli")), qPrintable(r.out.left(400)));
    }

    // Every option in Qt's list (--name) is in the synopsis above it too.
    void synopsisNamesEveryOption_data() { usageNamesTheCommand_data(); }
    void synopsisNamesEveryOption()
    {
        QFETCH(QString, command);
        const auto r = help(command);
        QVERIFY2(r.code == 0, qPrintable(r.err));
        const qsizetype at = r.out.indexOf(QLatin1String("\nOptions:"));
        QVERIFY(at >= 0);
        const QString top = synopsis(r.out);
        static const QRegularExpression option(QStringLiteral("^\\s+(?:-(\\w), )?--([\\w-]+)"),
                                               QRegularExpression::MultilineOption);
        QStringList missing;
        for (auto it = option.globalMatch(r.out.mid(at)); it.hasNext();) {
            const QRegularExpressionMatch m = it.next();
            const QString name = m.captured(2);
            // Qt's own (--help, --help-all), and an option the synopsis gives by its short name (-o).
            if (name.startsWith(QLatin1String("help"))
                || (!m.captured(1).isEmpty() && top.contains(QStringLiteral("-%1 ").arg(m.captured(1)))))
                continue;
            static const QRegularExpression boundary(QStringLiteral("[^\\w-]"));
            bool found = false;
            for (qsizetype i = top.indexOf(QStringLiteral("--") + name); i >= 0 && !found;
                 i = top.indexOf(QStringLiteral("--") + name, i + 1)) {
                const qsizetype end = i + 2 + name.size();
                found = end >= top.size() || boundary.match(top.mid(end, 1)).hasMatch();
            }
            if (!found)
                missing << name;
        }
        QVERIFY2(missing.isEmpty(), qPrintable(QStringLiteral("%1 --help: not in the synopsis: --%2\n%3")
                                                   .arg(command, missing.join(QStringLiteral(", --")), top)));
    }

    // can: every subcommand it runs, in its synopsis line, in its own line and in Qt's list.
    void canListsEverySubcommand()
    {
        const auto r = help(QStringLiteral("can"));
        QVERIFY2(r.code == 0, qPrintable(r.err));
        const QString first = r.out.section(QLatin1Char('\n'), 0, 0);
        const QString top = synopsis(r.out);
        const QString arguments = r.out.mid(r.out.indexOf(QLatin1String("\nArguments:")));
        for (const QString &sub : kCanSubcommands) {
            QVERIFY2(first.contains(QRegularExpression(QStringLiteral("[ |]%1[ |]").arg(sub))), qPrintable(sub + u'\n' + first));
            QVERIFY2(top.contains(QRegularExpression(QStringLiteral("\\n  %1\\b").arg(sub))), qPrintable(sub + u'\n' + top));
            QVERIFY2(arguments.contains(QRegularExpression(QStringLiteral("\\b%1\\b").arg(sub))),
                     qPrintable(sub + u'\n' + arguments));
        }
        // The overview (imudesk-cli --help) names them too.
        const auto all = imudesk::test::runCli({QStringLiteral("--help")}, 30000);
        const qsizetype can = all.out.indexOf(QLatin1String("\n  can "));
        QVERIFY(can >= 0);
        const QString entry = all.out.mid(can, all.out.indexOf(QLatin1String("CAN devices"), can) - can);
        for (const QString &sub : kCanSubcommands)
            QVERIFY2(entry.contains(QRegularExpression(QStringLiteral("[ |]%1[ |]").arg(sub))), qPrintable(sub + u'\n' + entry));
    }
};

IMUDESK_TEST_GUILESS_MAIN(TstCliHelp)
#include "tst_cli_help.moc"
