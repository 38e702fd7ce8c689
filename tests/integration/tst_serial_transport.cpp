// The serial transport (core/io/serial_transport.h) on a pseudo-terminal: what it takes for a lost
// link and what it does not.
#include "io/serial_transport.h"
#include "../common/raw_pty.h"
#include "../common/test_main.h"

#include <QSignalSpy>
#include <QTest>

using namespace imudesk;

class TstSerialTransport : public QObject {
    Q_OBJECT
private Q_SLOTS:
    // The flake of tst_link_opener(hec495) (issue 54): a family's baud scan flushes the port's
    // input (Transport::clear) in the same turn of the event loop as a notification of bytes that
    // had arrived; QSerialPort then reads nothing and reports a ReadError carrying a stale errno
    // ("Inappropriate ioctl for device"), which was taken for a pulled cable. It is no lost link;
    // a hang-up still is.
    void inputFlushedUnderANotificationIsNoLostLink()
    {
        test::RawPty pty;
        QVERIFY(pty.ok());
        io::SerialTransport t;
        QString error;
        QVERIFY2(t.open(pty.slave(), 115200, &error), qPrintable(error));
        QSignalSpy failed(&t, &io::Transport::failed);
        QSignalSpy received(&t, &io::Transport::bytesReceived);
        for (int round = 0; round < 40; ++round) {
            pty.write(std::vector<uint8_t>(64, 0x55));
            // Queued: it runs in the loop's next turn, before the port's notification of the bytes,
            // which that turn delivers after it.
            bool cleared = false;
            QMetaObject::invokeMethod(&t, [&t, &cleared] { t.clear(); cleared = true; }, Qt::QueuedConnection);
            QTRY_VERIFY(cleared);
        }
        QVERIFY2(failed.isEmpty(), failed.isEmpty() ? "" : qPrintable(failed.first().first().toString()));
        pty.write(std::vector<uint8_t>(8, 0xAA)); // still reading
        QTRY_VERIFY(!received.isEmpty() && received.last().first().toByteArray().endsWith(QByteArray(8, char(0xAA))));
        pty.pull();
        QTRY_VERIFY(!failed.isEmpty());
        t.close(); // as the session engine does on a lost link
        QVERIFY(failed.first().first().toString().contains(QLatin1String("was lost")));
    }
};

IMUDESK_TEST_MAIN(TstSerialTransport)
#include "tst_serial_transport.moc"
