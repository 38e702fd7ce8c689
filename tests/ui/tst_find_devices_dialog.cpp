// Device > Find devices… (issue 56), offscreen, on the simulated bench: every device in the
// table with its rate and address, the conflict on CAN node 5 in red with its evidence, the
// silent port said so, Connect opens the row's device with what the sweep found (and keeps the
// simulated device alive), Cancel stops a sweep at once, the fields are remembered, and the
// window keeps its table and findings in view at 1366x768 in English and Chinese.
#include "ui/discovery/find_devices_dialog.h"
#include "workspace/language_switcher.h"
#include "../common/layout_checks.h"
#include "../common/test_main.h"
#include "../common/test_paths.h"
#include "../common/try_bounds.h"

#include <QCheckBox>
#include <QDir>
#include <QLineEdit>
#include <QListWidget>
#include <QPushButton>
#include <QSettings>
#include <QTableWidget>
#include <QTest>

using namespace imudesk;
using ui::FindDevicesDialog;

namespace {

const QString kCan = QStringLiteral("tcp://127.0.0.1:24503/can0");

int rowOf(const QTableWidget *t, const QString &rate)
{
    for (int r = 0; r < t->rowCount(); ++r)
        if (t->item(r, FindDevicesDialog::ColRate)->text() == rate)
            return r;
    return -1;
}

} // namespace

class TstFindDevicesDialog : public QObject {
    Q_OBJECT

    QList<device::LinkRequest> m_opened;
    std::unique_ptr<FindDevicesDialog> m_dialog; // one sweep of the bench, looked at by several tests

    FindDevicesDialog::ConnectFn recorder()
    {
        return [this](device::LinkRequest r, QString *) {
            m_opened.append(std::move(r));
            return true;
        };
    }

private Q_SLOTS:
    void initTestCase()
    {
        // Settings of this test's own, never the user's.
        QCoreApplication::setOrganizationName(QStringLiteral("ImuDeskTest"));
        QCoreApplication::setApplicationName(QStringLiteral("tst_find_devices_dialog"));
        QSettings().clear();
        m_dialog = std::make_unique<FindDevicesDialog>(recorder());
        m_dialog->resize(1326, 700);
        m_dialog->show();
        QVERIFY(m_dialog->useSimulatedBench(true, kCan));
        m_dialog->onlyListedBox()->setChecked(true); // the machine's own ports are not this test's
        m_dialog->setTimeLimit(45);
        m_dialog->start();
        QVERIFY(m_dialog->isRunning());
        QVERIFY(!m_dialog->startButton()->isEnabled());
        QVERIFY(m_dialog->cancelButton()->isEnabled());
        QVERIFY(test::waitFor([&] { return !m_dialog->isRunning(); }, 60000));
    }

    void everyDeviceWithItsRateAndAddress()
    {
        const QTableWidget *t = m_dialog->table();
        QVERIFY2(t->rowCount() >= 5, qPrintable(m_dialog->statusText()));
        const int hipnuc = rowOf(t, QStringLiteral("460800 baud"));
        QVERIFY(hipnuc >= 0);
        QVERIFY(t->item(hipnuc, FindDevicesDialog::ColModel)->text().startsWith(QStringLiteral("HI14")));
        const int hec = rowOf(t, QStringLiteral("4800 baud"));
        QVERIFY(hec >= 0);
        QCOMPARE(t->item(hec, FindDevicesDialog::ColAddress)->text(), QStringLiteral("7"));
        const int modbus = rowOf(t, QStringLiteral("38400 baud"));
        QVERIFY(modbus >= 0);
        QCOMPARE(t->item(modbus, FindDevicesDialog::ColAddress)->text(), QStringLiteral("17"));
        QCOMPARE(t->item(modbus, FindDevicesDialog::ColLink)->text(), QStringLiteral("Modbus RTU"));
        int canRows = 0;
        for (int r = 0; r < t->rowCount(); ++r)
            if (t->item(r, FindDevicesDialog::ColLink)->text() == QLatin1String("CAN")) {
                ++canRows;
                QCOMPARE(t->item(r, FindDevicesDialog::ColRate)->text(), QStringLiteral("500 kbit/s"));
            }
        QCOMPARE(canRows, 2); // the J1939 module and node 5 (twice over: the conflict)
        QVERIFY(m_dialog->connectAllButton()->isEnabled());
    }

    void conflictInRedAndTheSilentPort()
    {
        const QListWidget *f = m_dialog->findings();
        bool conflict = false, silent = false;
        for (int i = 0; i < f->count(); ++i) {
            const QListWidgetItem *item = f->item(i);
            if (item->text().startsWith(QLatin1String("Conflict"))) {
                conflict = true;
                QVERIFY(item->text().contains(QLatin1String("node 5")));
                QVERIFY(item->text().contains(QLatin1String("What to do")));
                QCOMPARE(item->foreground().color(), QColor(0xB0, 0x00, 0x20));
            }
            silent = silent || item->text().contains(QLatin1String("(silent)"))
                || item->text().contains(QLatin1String("(out of time)"));
        }
        QVERIFY(conflict);
        QVERIFY(silent);
        QVERIFY2(m_dialog->statusText().contains(QLatin1String("conflict")) && m_dialog->statusText().contains(QLatin1String("see below")),
                 qPrintable(m_dialog->statusText()));
        // Node 5's row in red as well, the evidence in its tooltip.
        const QTableWidget *t = m_dialog->table();
        bool redRow = false;
        for (int r = 0; r < t->rowCount(); ++r)
            if (t->item(r, FindDevicesDialog::ColAddress)->text() == QLatin1String("node 5")) {
                redRow = t->item(r, FindDevicesDialog::ColPort)->foreground().color() == QColor(0xB0, 0x00, 0x20)
                    && t->item(r, FindDevicesDialog::ColPort)->toolTip().contains(QLatin1String("answers from node 5"));
            }
        QVERIFY(redRow);
    }

    void connectOpensTheDeviceAsFound()
    {
        m_opened.clear();
        const int modbus = rowOf(m_dialog->table(), QStringLiteral("38400 baud"));
        auto *button = qobject_cast<QPushButton *>(m_dialog->table()->cellWidget(modbus, FindDevicesDialog::ColConnect));
        QVERIFY(button);
        button->click();
        QCOMPARE(m_opened.size(), 1);
        const device::LinkRequest &r = m_opened.front();
        QCOMPARE(r.kind, device::LinkRequest::Kind::Modbus);
        QCOMPARE(r.modbus.nodeId, 17);
        QCOMPARE(r.modbus.baud, 38400);
        QVERIFY(r.keepAlive); // the simulated bench lives as long as the tab
        QVERIFY(!button->isEnabled());
        const int hec = rowOf(m_dialog->table(), QStringLiteral("4800 baud"));
        QVERIFY(m_dialog->connectRow(hec));
        QCOMPARE(m_opened.back().kind, device::LinkRequest::Kind::Serial);
        QCOMPARE(m_opened.back().family, QStringLiteral("hec495"));
        QCOMPARE(m_opened.back().baud, 4800);
        QCOMPARE(m_opened.back().deviceAddress, 7);
        // Connect all opens the rest, each once.
        m_opened.clear();
        m_dialog->connectAllButton()->click();
        QCOMPARE(m_opened.size(), m_dialog->table()->rowCount() - 2);
        QVERIFY(!m_dialog->connectAllButton()->isEnabled());
    }

    void fitsAt1366x768_data()
    {
        QTest::addColumn<QString>("language");
        QTest::newRow("en") << QStringLiteral("en");
        QTest::newRow("zh_CN") << QStringLiteral("zh_CN");
    }
    void fitsAt1366x768()
    {
        QFETCH(QString, language);
        ui::LanguageSwitcher switcher;
        QString error;
        QVERIFY2(switcher.setLanguage(language, QString::fromUtf8(IMUDESK_QM_DIR), &error), qPrintable(error));
        m_dialog->setGeometry(QRect(QPoint(0, 0), QSize(1366, 768)).adjusted(20, 20, -20, -60));
        QVERIFY(test::layout::layoutSettled(*m_dialog));
        QStringList problems = test::layout::cutOrOutside(*m_dialog);
        // Every column of the table in view, no horizontal scroll bar.
        const QTableWidget *t = m_dialog->table();
        int width = 0;
        for (int c = 0; c < t->columnCount(); ++c)
            width += t->columnWidth(c);
        if (width > t->viewport()->width())
            problems << QStringLiteral("the table's columns need %1 px of %2").arg(width).arg(t->viewport()->width());
        const QString shots = qEnvironmentVariable("IMUDESK_LAYOUT_SHOTS");
        if (!shots.isEmpty())
            m_dialog->grab().save(QDir(shots).filePath(QStringLiteral("find-devices-1366x768-%1.png").arg(language)));
        QVERIFY(switcher.setLanguage(QStringLiteral("en"), QString::fromUtf8(IMUDESK_QM_DIR), &error));
        QVERIFY2(problems.isEmpty(), qPrintable(problems.join(QLatin1Char('\n'))));
    }

    void fieldsAreRemembered()
    {
        m_dialog->portsEdit()->setText(QStringLiteral("/dev/pts/99"));
        m_dialog->reject();
        FindDevicesDialog again(recorder());
        QVERIFY2(again.portsEdit()->text().contains(QLatin1String("/dev/pts/99")), qPrintable(again.portsEdit()->text()));
        QVERIFY(!again.portsEdit()->text().contains(QLatin1String("/dev/pts/0,"))); // not the bench's
    }

    void cancelStopsAtOnce()
    {
        FindDevicesDialog d(recorder());
        d.portsEdit()->setText(QStringLiteral("/dev/null"));
        d.busesEdit()->clear();
        d.onlyListedBox()->setChecked(true);
        d.start();
        d.cancel();
        QVERIFY(!d.isRunning());
        QVERIFY(d.result().cancelled);
        QVERIFY(d.startButton()->isEnabled());
        QVERIFY2(d.statusText().contains(QLatin1String("Cancelled")), qPrintable(d.statusText()));
    }

    void cleanupTestCase() { m_dialog.reset(); }
};

IMUDESK_TEST_MAIN(TstFindDevicesDialog)
#include "tst_find_devices_dialog.moc"
