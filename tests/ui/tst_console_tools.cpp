// Console tools, offscreen: command completion in the console input, the raw byte view
// of the link (hex/ASCII, colours, pause, clear, copy, bounded, fast enough for 921600
// baud) and the log of the commands the GUI sent (model and widget, copy as text).
#include "workspace/command_log_widget.h"
#include "workspace/console_widget.h"
#include "device/device_session.h"
#include "device/raw_byte_log.h"
#include "itemmodels/command_log_model.h"
#include "protocol/hipnuc/ascii_command.h"
#include "workspace/raw_bytes_view.h"
#include "../common/test_main.h"

#include <QAbstractItemModelTester>
#include <QApplication>
#include <QClipboard>
#include <QCompleter>
#include <QItemSelectionModel>
#include <QLineEdit>
#include <QPlainTextEdit>
#include <QSignalSpy>
#include <QTableView>
#include <QTest>
#include <QTextBlock>

using imudesk::device::RawByteLog;
using imudesk::models::CommandLogModel;
using imudesk::device::TextReply;
using imudesk::ui::CommandLogWidget;
using imudesk::ui::ConsoleWidget;
using imudesk::ui::RawBytesView;
namespace commands = imudesk::protocol::hipnuc::commands;

namespace {

QStringList completions(QCompleter *completer)
{
    QStringList out;
    for (int i = 0; i < completer->completionCount(); ++i) {
        completer->setCurrentRow(i);
        out << completer->currentCompletion();
    }
    return out;
}

// The colour of the first block whose text contains `needle`.
QColor colourOf(const RawBytesView &view, const QString &needle)
{
    for (QTextBlock b = view.textView()->document()->begin(); b.isValid(); b = b.next())
        if (b.text().contains(needle) && b.begin() != b.end())
            return b.begin().fragment().charFormat().foreground().color();
    return QColor();
}

TextReply reply(TextReply::Status status, QStringList lines, const QString &error = {})
{
    TextReply r;
    r.status = status;
    r.lines = std::move(lines);
    r.why = error;
    return r;
}

const QDateTime kWhen(QDate(2025, 3, 4), QTime(10, 11, 12, 345));

} // namespace

class TstConsoleTools : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void documentedCommandsFollowTheBuilders()
    {
        QStringList all = imudesk::device::DeviceSession::documentedCommands();
        for (const char *c : {"LOG VERSION", "LOG COMCONFIG", "LOG HI91 ONTIME 0.01", "LOG HI91 ONTIME 0.001",
                              "LOG DISABLE", "LOG ENABLE", "CONFIG ATT MODE 1", "SERIALCONFIG 115200",
                              "SERIALCONFIG 921600", "SAVECONFIG", "REBOOT", "FRESET", "LOG MCAL STAT",
                              "CONFIG MCAL START", "LOG MAGCONFIG", "CONFIG YAW 0 0"})
            QVERIFY2(all.contains(QLatin1String(c)), c);
        QVERIFY(all.contains(QString::fromStdString(commands::imuUrfr(24).text)));
        QVERIFY(all.contains(QString::fromStdString(commands::logHi83Map(0xFF).text)));
        QCOMPARE(all.removeDuplicates(), 0);
        for (const QString &c : all)
            QVERIFY2(c == c.trimmed() && !c.isEmpty() && c == c.toUpper().replace(QLatin1String("0X"), QLatin1String("0x")),
                     qPrintable(c));
    }

    void completionOffersCommands()
    {
        ConsoleWidget console;
        console.setCompletions(imudesk::device::DeviceSession::documentedCommands());
        console.show();
        QVERIFY(QTest::qWaitForWindowExposed(&console));
        QLineEdit *input = console.input();
        QCOMPARE(input->completer(), console.completer());
        input->setFocus();
        QTest::keyClicks(input, QStringLiteral("LOG V"));
        QCOMPARE(console.completer()->completionPrefix(), QStringLiteral("LOG V"));
        QCOMPARE(completions(console.completer()), QStringList{QStringLiteral("LOG VERSION")});
        QTRY_VERIFY(console.completer()->popup()->isVisible());

        // Case does not matter; every command with the prefix is offered.
        input->clear();
        QTest::keyClicks(input, QStringLiteral("log hi91 on"));
        const QStringList hi91 = completions(console.completer());
        QVERIFY(hi91.contains(QStringLiteral("LOG HI91 ONTIME 0.01")));
        QVERIFY(hi91.contains(QStringLiteral("LOG HI91 ONMARK 1")));
        for (const QString &c : hi91)
            QVERIFY(c.startsWith(QLatin1String("LOG HI91 ON")));

        // Choosing a completion and pressing Enter sends it.
        QSignalSpy submitted(&console, &ConsoleWidget::commandSubmitted);
        input->clear();
        QTest::keyClicks(input, QStringLiteral("CONFIG ATT M"));
        QTRY_VERIFY(console.completer()->popup()->isVisible());
        QTest::keyClick(console.completer()->popup(), Qt::Key_Down);
        QTest::keyClick(console.completer()->popup(), Qt::Key_Return);
        QTRY_COMPARE(submitted.size(), 1);
        QVERIFY(submitted.at(0).at(0).toString().startsWith(QLatin1String("CONFIG ATT MODE ")));

        // History still walks with Up when no completion is shown.
        QTRY_VERIFY(!console.completer()->popup()->isVisible());
        QTest::keyClick(input, Qt::Key_Up);
        QCOMPARE(input->text(), submitted.at(0).at(0).toString());
    }

    void rawBytesShowHexAsciiAndDirection()
    {
        RawByteLog log;
        // A frame start (5A A5), a command and its OK.
        log.append(RawByteLog::Direction::Rx, QByteArray::fromHex("5aa54c0091"), 1'000'000'000);
        log.append(RawByteLog::Direction::Tx, QByteArrayLiteral("LOG VERSION\r\n"), 1'250'000'000);
        log.append(RawByteLog::Direction::Rx, QByteArrayLiteral("OK\r\n"), 1'500'000'000);
        RawBytesView view;
        view.setLog(&log);
        view.show();
        view.refresh();
        const QString text = view.text();
        QVERIFY2(text.contains(QLatin1String("5A A5 4C 00 91")), qPrintable(text));
        QVERIFY2(text.contains(QLatin1String("|Z.L..|")), qPrintable(text));
        QVERIFY2(text.contains(QLatin1String("4C 4F 47 20 56")), qPrintable(text)); // "LOG V"
        QVERIFY(text.contains(QLatin1String("|LOG VERSION..|")));
        QVERIFY(text.contains(QLatin1String("4F 4B 0D 0A")));
        QVERIFY(text.contains(QLatin1String("|OK..|")));
        const QStringList lines = text.split(QLatin1Char('\n'));
        QCOMPARE(lines.size(), 3);
        // Time since the first chunk, direction, offset in that direction.
        QVERIFY2(lines[0].startsWith(QLatin1String("    0.000 RX 00000000  5A")), qPrintable(lines[0]));
        QVERIFY2(lines[1].startsWith(QLatin1String("    0.250 TX 00000000  4C")), qPrintable(lines[1]));
        QVERIFY2(lines[2].startsWith(QLatin1String("    0.500 RX 00000005  4F")), qPrintable(lines[2]));
        // Received and sent bytes in different colours.
        QCOMPARE(colourOf(view, QStringLiteral("|Z.L..|")), RawBytesView::rxColor());
        QCOMPARE(colourOf(view, QStringLiteral("|LOG VERSION..|")), RawBytesView::txColor());
        QVERIFY(RawBytesView::rxColor() != RawBytesView::txColor());

        // Only what is new is added.
        view.refresh();
        QCOMPARE(view.text(), text);
        const QByteArray longer(40, 'A');
        log.append(RawByteLog::Direction::Rx, longer, 2'000'000'000);
        view.refresh();
        const QStringList more = view.text().split(QLatin1Char('\n'));
        QCOMPARE(more.size(), 6); // 40 bytes: 16 + 16 + 8
        QVERIFY(more[3].startsWith(QLatin1String("    1.000 RX 00000009  41 41")));
        QVERIFY(more[4].contains(QLatin1String("RX 00000019")));
        QVERIFY(more[5].contains(QLatin1String("|AAAAAAAA|")));
    }

    void rawLogHoldsBytesNotSpareCapacity()
    {
        // A read buffer with 16 KiB of spare capacity (what QIODevice::readAll() returns) is
        // held at its size; a chunk that is already tight is shared, not copied.
        RawByteLog log(1024);
        QByteArray read;
        read.reserve(16384);
        read.append(QByteArray::fromHex("5aa54c0091"));
        log.append(RawByteLog::Direction::Rx, read, 0);
        const QByteArray tight = QByteArrayLiteral("OK\r\n").toLower().toUpper(); // heap, exact size
        log.append(RawByteLog::Direction::Rx, tight, 1);
        const std::vector<RawByteLog::Chunk> held = log.since(0);
        QCOMPARE(held.size(), size_t(2));
        QCOMPARE(held[0].bytes, read);
        QVERIFY2(held[0].bytes.capacity() <= held[0].bytes.size() + RawByteLog::kSpareCapacity,
                 qPrintable(QString::number(held[0].bytes.capacity())));
        QCOMPARE(held[1].bytes.constData(), tight.constData());
        // Larger than the whole log: only the newest bytes, at their size.
        QByteArray big(3000, 'x');
        big[2999] = 'y';
        log.append(RawByteLog::Direction::Rx, big, 2);
        const std::vector<RawByteLog::Chunk> last = log.since(2);
        QCOMPARE(last.size(), size_t(1));
        QCOMPARE(last[0].bytes.size(), 1024);
        QCOMPARE(last[0].bytes.back(), 'y');
        QCOMPARE(log.bytesHeld(), size_t(1024));
    }

    void rawBytesPauseClearCopy()
    {
        RawByteLog log;
        RawBytesView view;
        view.setLog(&log);
        log.append(RawByteLog::Direction::Rx, QByteArrayLiteral("first\r\n"), 0);
        view.refresh();
        QVERIFY(view.text().contains(QLatin1String("|first..|")));

        view.setPaused(true);
        QVERIFY(view.isPaused());
        log.append(RawByteLog::Direction::Rx, QByteArrayLiteral("second"), 1000);
        view.refresh();
        QVERIFY(!view.text().contains(QLatin1String("second")));
        view.setPaused(false);
        view.refresh();
        QVERIFY(view.text().contains(QLatin1String("|second|")));

        // Copy: everything shown, or the selection.
        view.copyToClipboard();
        QCOMPARE(QGuiApplication::clipboard()->text(), view.text());
        QTextCursor cursor(view.textView()->document());
        cursor.movePosition(QTextCursor::EndOfBlock, QTextCursor::KeepAnchor);
        view.textView()->setTextCursor(cursor);
        QCOMPARE(view.copyText(), view.text().split(QLatin1Char('\n')).first());
        view.copyToClipboard();
        QCOMPARE(QGuiApplication::clipboard()->text(), view.copyText());

        // Clear: gone, and not shown again; what comes after is.
        view.clear();
        QVERIFY(view.text().isEmpty());
        view.refresh();
        QVERIFY(view.text().isEmpty());
        log.append(RawByteLog::Direction::Tx, QByteArrayLiteral("third"), 2000);
        view.refresh();
        QVERIFY(view.text().contains(QLatin1String("TX 00000000")));
        QVERIFY(view.text().contains(QLatin1String("|third|")));
        QVERIFY(!view.text().contains(QLatin1String("first")));
        // Offsets count what was cleared.
        log.append(RawByteLog::Direction::Rx, QByteArrayLiteral("x"), 3000);
        view.refresh();
        QVERIFY2(view.text().contains(QLatin1String("RX 0000000D")), qPrintable(view.text())); // 7 + 6 bytes before
    }

    void rawBytesAreBounded()
    {
        RawByteLog log(1024 * 1024);
        RawBytesView view;
        view.setMaxBytes(4096);
        view.setLog(&log);
        QByteArray chunk(100, '\x5a');
        for (int i = 0; i < 1000; ++i) // 100 kB since the last refresh
            log.append(RawByteLog::Direction::Rx, chunk, int64_t(i) * 1000);
        view.refresh();
        QVERIFY(view.text().contains(QLatin1String("not shown")));
        const int blocks = view.textView()->document()->blockCount();
        QVERIFY2(blocks <= 4096 / 16 + 64 + 2, qPrintable(QString::number(blocks)));
        // Many small refreshes stay bounded too.
        for (int i = 0; i < 200; ++i) {
            log.append(RawByteLog::Direction::Rx, chunk, int64_t(1000 + i) * 1000);
            view.refresh();
        }
        QVERIFY(view.textView()->document()->blockCount() <= 4096 / 16 + 64 + 2);
    }

    void rawBytesStayBoundedAt921600()
    {
        // 921600 baud: ~92 kB/s, read in chunks of a few hundred bytes; the view refreshes
        // at 30 Hz and keeps only its bounded tail. (Its speed is measured by the GUI
        // benchmark, tests/bench/bench_gui_live, not here.)
        RawByteLog log;
        RawBytesView view;
        view.resize(900, 400);
        view.setLog(&log);
        view.show();
        QVERIFY(QTest::qWaitForWindowExposed(&view));
        QByteArray chunk(256, '\0');
        for (int i = 0; i < chunk.size(); ++i)
            chunk[i] = char(i * 37);
        int64_t now = 0;
        constexpr int kTicks = 90; // 3 s
        for (int tick = 0; tick < kTicks; ++tick) {
            for (int c = 0; c < 12; ++c) // 3 kB per 33 ms
                log.append(RawByteLog::Direction::Rx, chunk, now += 2'700'000);
            view.refresh();
            QCoreApplication::processEvents(); // paint
        }
        QVERIFY(view.textView()->document()->blockCount() <= int(RawBytesView::kDefaultMaxBytes / 16) + 64 + 2);
    }

    void commandLogModelRecordsOutcomes()
    {
        CommandLogModel model;
        QAbstractItemModelTester tester(&model, QAbstractItemModelTester::FailureReportingMode::QtTest);
        QCOMPARE(model.columnCount(), 4);
        QCOMPARE(model.headerData(CommandLogModel::StatusColumn, Qt::Horizontal).toString(), QStringLiteral("Status"));
        model.record(1, QStringLiteral("LOG VERSION"), kWhen);
        model.record(2, QStringLiteral("CONFIG ATT MODE 7"), kWhen.addMSecs(100));
        model.record(3, QStringLiteral("FOO BAR"), kWhen.addMSecs(200));
        QCOMPARE(model.rowCount(), 3);
        QCOMPARE(model.index(0, CommandLogModel::StatusColumn).data().toString(), QStringLiteral("waiting"));

        QVERIFY(model.complete(1, reply(TextReply::Status::Ok, {"PNAME=HI14R3", "APP_VER=171"})));
        QVERIFY(model.complete(2, reply(TextReply::Status::Refused, {}, QStringLiteral("ERR"))));
        QVERIFY(model.complete(3, reply(TextReply::Status::Timeout, {}, QStringLiteral("no reply within 1000 ms"))));
        QVERIFY(!model.complete(99, reply(TextReply::Status::Ok, {})));

        auto cell = [&](int row, int column) { return model.index(row, column).data().toString(); };
        QCOMPARE(cell(0, CommandLogModel::TimeColumn), QStringLiteral("10:11:12.345"));
        QCOMPARE(cell(0, CommandLogModel::CommandColumn), QStringLiteral("LOG VERSION"));
        QCOMPARE(cell(0, CommandLogModel::StatusColumn), QStringLiteral("OK"));
        QCOMPARE(cell(0, CommandLogModel::ReplyColumn), QStringLiteral("PNAME=HI14R3 | APP_VER=171"));
        QCOMPARE(cell(1, CommandLogModel::StatusColumn), QStringLiteral("ERR"));
        QCOMPARE(cell(1, CommandLogModel::ReplyColumn), QStringLiteral("ERR"));
        QCOMPARE(cell(2, CommandLogModel::StatusColumn), QStringLiteral("timeout"));
        QCOMPARE(cell(2, CommandLogModel::ReplyColumn), QStringLiteral("no reply within 1000 ms"));
        QCOMPARE(model.index(1, 0).data(CommandLogModel::StatusRole).toInt(), int(TextReply::Status::Refused));
        QCOMPARE(model.index(2, 0).data(CommandLogModel::IdRole).toULongLong(), quint64(3));

        // Copy as text: tab-separated, rows in order, a header when asked.
        QCOMPARE(model.rowsAsText({2, 0}),
                 QStringLiteral("10:11:12.345\tLOG VERSION\tOK\tPNAME=HI14R3 | APP_VER=171\n"
                                "10:11:12.545\tFOO BAR\ttimeout\tno reply within 1000 ms\n"));
        QCOMPARE(model.allAsText(true).split(QLatin1Char('\n')).first(), QStringLiteral("Time\tCommand\tStatus\tReply"));
        QCOMPARE(model.allAsText().count(QLatin1Char('\n')), 3);
        QVERIFY(model.rowsAsText({}).isEmpty());

        // Bounded: the oldest rows go.
        for (int i = 0; i < CommandLogModel::kMaxRows; ++i)
            model.record(quint64(100 + i), QStringLiteral("LOG VERSION"), kWhen);
        QCOMPARE(model.rowCount(), CommandLogModel::kMaxRows);
        QCOMPARE(model.index(0, 0).data(CommandLogModel::IdRole).toULongLong(), quint64(100)); // 1-3 dropped
        QVERIFY(!model.complete(1, reply(TextReply::Status::Ok, {})));
        model.clear();
        QCOMPARE(model.rowCount(), 0);
    }

    void commandLogWidgetCopies()
    {
        CommandLogWidget widget;
        widget.show();
        QVERIFY(QTest::qWaitForWindowExposed(&widget));
        widget.record(1, QStringLiteral("LOG VERSION"));
        widget.record(2, QStringLiteral("CONFIG ATT MODE 7"));
        widget.record(3, QStringLiteral("LOG COMCONFIG"));
        QVERIFY(widget.complete(1, reply(TextReply::Status::Ok, {"PNAME=HI14R3"})));
        QVERIFY(widget.complete(2, reply(TextReply::Status::Refused, {}, QStringLiteral("ERR"))));
        QVERIFY(!widget.complete(42, reply(TextReply::Status::Ok, {})));
        QCOMPARE(widget.model()->rowCount(), 3);

        // Rows 0 and 2 selected (one cell each is enough: whole rows are copied).
        QItemSelectionModel *selection = widget.view()->selectionModel();
        selection->select(widget.model()->index(0, 1), QItemSelectionModel::Select | QItemSelectionModel::Rows);
        selection->select(widget.model()->index(2, 3), QItemSelectionModel::Select | QItemSelectionModel::Rows);
        const QString expected = widget.model()->rowsAsText({0, 2}, true);
        QCOMPARE(widget.selectedText(), expected);
        QVERIFY(expected.startsWith(QLatin1String("Time\tCommand\tStatus\tReply\n")));
        QCOMPARE(expected.count(QLatin1Char('\n')), 3);
        QVERIFY(expected.contains(QLatin1String("\tLOG VERSION\tOK\tPNAME=HI14R3\n")));
        QVERIFY(expected.contains(QLatin1String("\tLOG COMCONFIG\twaiting\t\n")));
        QVERIFY(!expected.contains(QLatin1String("ATT MODE")));

        QGuiApplication::clipboard()->clear();
        widget.copySelected();
        QCOMPARE(QGuiApplication::clipboard()->text(), expected);
        widget.copyAll();
        QCOMPARE(QGuiApplication::clipboard()->text(), widget.model()->allAsText(true));
        QVERIFY(QGuiApplication::clipboard()->text().contains(QLatin1String("\tCONFIG ATT MODE 7\tERR\tERR\n")));

        // Ctrl+C in the table copies the selection.
        QGuiApplication::clipboard()->clear();
        widget.view()->setFocus();
        QTest::keySequence(widget.view(), QKeySequence::Copy);
        QCOMPARE(QGuiApplication::clipboard()->text(), expected);

        widget.clear();
        QCOMPARE(widget.model()->rowCount(), 0);
    }
};

IMUDESK_TEST_MAIN(TstConsoleTools)
#include "tst_console_tools.moc"
