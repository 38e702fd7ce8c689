// The translations are complete: no .ts entry is unfinished or obsolete, and under zh_CN
// no English word is left in the main window, its docks and menus, or the dialogs.
#include "../common/ui_families.h"
#include "calibration/attitude_reset_wizard.h"
#include "charts/bandwidth_calculator.h"
#include "bus/bus_connect_dialog.h"
#include "workspace/device_workspace.h"
#include "recording/export_dialog.h"
#include "ui/firmware/firmware_update_dialog.h"
#include "calibration/gyro_scale_wizard.h"
#include "charts/analysis_window.h"
#include "calibration/mag_calibration_wizard.h"
#include "configuration/profile_dialog.h"
#include "bridge/live_bridge_dialog.h"
#include "workspace/language_switcher.h"
#include "workspace/main_window.h"
#include "workspace/preferences_dialog.h"
#include "../common/test_main.h"

#include <QAbstractButton>
#include <QAbstractItemView>
#include <QAction>
#include <QApplication>
#include <QComboBox>
#include <QDir>
#include <QDockWidget>
#include <QFile>
#include <QGroupBox>
#include <QLabel>
#include <QLineEdit>
#include <QMenu>
#include <QRegularExpression>
#include <QSet>
#include <QTabBar>
#include <QTest>
#include <QTextDocument>
#include <QWizard>
#include <QXmlStreamReader>

using namespace imudesk;

namespace {

QString translationsDir()
{
    // IMUDESK_TEST_DATA is <source>/tests/data (which need not exist: clean the path first).
    return QDir::cleanPath(QString::fromUtf8(IMUDESK_TEST_DATA) + QStringLiteral("/../../translations"));
}

// Words that stay as they are in every language: units, product and program names, and
// what a user types or reads on the wire. All-capital words (LOG, HI91, ENU, WB_CONV) are
// commands, frame names and flags and stay too.
const QSet<QString> &keptWords()
{
    static const QSet<QString> words = {
        QStringLiteral("deg"), QStringLiteral("rad"), QStringLiteral("min"), QStringLiteral("ms"),
        QStringLiteral("Hz"), QStringLiteral("kHz"), QStringLiteral("ppm"), QStringLiteral("ImuDesk"), QStringLiteral("HiPNUC"),
        QStringLiteral("Witlink"), QStringLiteral("English"), QStringLiteral("imudesk"), QStringLiteral("cli"),
        QStringLiteral("dev"), QStringLiteral("pts"), QStringLiteral("tty"), QStringLiteral("ttyUSB"),
        QStringLiteral("ttyACM"), QStringLiteral("Modbus"), QStringLiteral("CANopen"), QStringLiteral("imucap"),
        QStringLiteral("png"), QStringLiteral("csv"), QStringLiteral("json"), QStringLiteral("jsonl"),
        QStringLiteral("hex"), QStringLiteral("bin"), QStringLiteral("virtualcan"), QStringLiteral("socketcan"),
        QStringLiteral("device"), QStringLiteral("product"), QStringLiteral("serial"), QStringLiteral("date"), QStringLiteral("time"),
        QStringLiteral("Ctrl"), QStringLiteral("Shift"), QStringLiteral("Alt"), QStringLiteral("Pause"), QStringLiteral("ttyS"),
        QStringLiteral("Linux"), QStringLiteral("socketcan"), QStringLiteral("peakcan"), QStringLiteral("can"),
        QStringLiteral("kbit"), QStringLiteral("Mbit"), QStringLiteral("bit"), QStringLiteral("pandas"), QStringLiteral("PlotJuggler"), QStringLiteral("Foxglove"), QStringLiteral("Lichtblick"),
        QStringLiteral("MATLAB"), QStringLiteral("mat"), QStringLiteral("mcap"), QStringLiteral("WebSocket"),
        // Other tools' menus as they name them (Foxglove's "Open connection", PlotJuggler's "Streaming >
        // Foxglove Bridge" and "UDP Server", its "timestamp" field), and the topics a device streams.
        QStringLiteral("Open"), QStringLiteral("connection"), QStringLiteral("Streaming"), QStringLiteral("Bridge"),
        QStringLiteral("Server"), QStringLiteral("timestamp"), QStringLiteral("imu"), QStringLiteral("mag"), QStringLiteral("euler"),
        QStringLiteral("status"),
        QStringLiteral("Intel"), QStringLiteral("dialout"), QStringLiteral("KiB"), QStringLiteral("MiB"),
        QStringLiteral("GiB"), QStringLiteral("udev"), QStringLiteral("usermod"), QStringLiteral("sudo"),
        QStringLiteral("USER"), QStringLiteral("rules"), QStringLiteral("FitErr"), QStringLiteral("imucap"),
        QStringLiteral("session"), // session.json, a recorded session's file name
        // Qt CAN plugin names, as QCanBus lists them.
        QStringLiteral("passthrucan"), QStringLiteral("tinycan"), QStringLiteral("vectorcan"),
        QStringLiteral("systeccan"), QStringLiteral("virtualcan"),
    };
    return words;
}

// The English words left in `text` (empty when it is fully translated).
QStringList englishWords(const QString &text)
{
    QString plain = text;
    if (Qt::mightBeRichText(plain)) {
        QTextDocument doc;
        doc.setHtml(plain);
        plain = doc.toPlainText();
    }
    plain.remove(QRegularExpression(QStringLiteral("\\{[a-z]+\\}"))); // {device} placeholders
    plain.remove(QLatin1Char('&'));                                 // mnemonics
    static const QRegularExpression word(QStringLiteral("[A-Za-z][A-Za-z_]*[A-Za-z]"));
    QStringList found;
    for (auto it = word.globalMatch(plain); it.hasNext();) {
        const QString w = it.next().captured();
        if (w.size() < 3 && w != QStringLiteral("of") && w != QStringLiteral("to") && w != QStringLiteral("on"))
            continue;
        // All capitals (LOG, HI91, WB_CONV) and field names with underscores (system_time) stay.
        if (w.toUpper() == w || w.contains(QLatin1Char('_')) || keptWords().contains(w))
            continue;
        found << w;
    }
    return found;
}

// Every user-visible text of a widget tree (and of the actions and menus it holds).
QStringList visibleTexts(QWidget *root)
{
    QStringList texts;
    const auto add = [&texts](const QString &t) {
        if (!t.trimmed().isEmpty())
            texts << t;
    };
    QList<QWidget *> widgets = root->findChildren<QWidget *>();
    widgets.prepend(root);
    for (QWidget *w : widgets) {
        if (w->isWindow())
            add(w->windowTitle());
        add(w->toolTip());
        if (auto *label = qobject_cast<QLabel *>(w))
            add(label->text());
        else if (auto *button = qobject_cast<QAbstractButton *>(w))
            add(button->text());
        else if (auto *group = qobject_cast<QGroupBox *>(w))
            add(group->title());
        else if (auto *edit = qobject_cast<QLineEdit *>(w))
            add(edit->placeholderText());
        else if (auto *dock = qobject_cast<QDockWidget *>(w))
            add(dock->windowTitle());
        else if (auto *tabs = qobject_cast<QTabBar *>(w))
            for (int i = 0; i < tabs->count(); ++i)
                add(tabs->tabText(i));
        if (auto *combo = qobject_cast<QComboBox *>(w)) {
            if (!combo->isEditable())
                for (int i = 0; i < combo->count(); ++i)
                    add(combo->itemText(i));
        }
        if (auto *view = qobject_cast<QAbstractItemView *>(w); view && view->model()) {
            QAbstractItemModel *m = view->model();
            for (int c = 0; c < m->columnCount(); ++c)
                add(m->headerData(c, Qt::Horizontal).toString());
            for (int r = 0; r < std::min(m->rowCount(), 200); ++r)
                add(m->index(r, 0).data().toString());
        }
        for (QAction *a : w->actions()) {
            add(a->text());
            add(a->toolTip() == QString(a->text()).remove(QLatin1Char('&')) ? QString() : a->toolTip());
        }
    }
    return texts;
}

void verifyTranslated(QWidget *root)
{
    QStringList untranslated;
    for (const QString &t : visibleTexts(root)) {
        const QStringList words = englishWords(t);
        if (!words.isEmpty())
            untranslated << QStringLiteral("%1  [%2]").arg(t.left(120), words.join(QLatin1Char(' ')));
    }
    untranslated.removeDuplicates();
    QVERIFY2(untranslated.isEmpty(),
             qPrintable(QStringLiteral("%1 untranslated text(s) in %2:\n  ")
                            .arg(untranslated.size())
                            .arg(root->metaObject()->className()) +
                        untranslated.join(QStringLiteral("\n  "))));
}

} // namespace

class TstTranslations : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void tsFilesAreComplete_data()
    {
        QTest::addColumn<QString>("file");
        QTest::newRow("zh_CN") << QStringLiteral("imudesk_zh_CN.ts");
        QTest::newRow("zh_TW") << QStringLiteral("imudesk_zh_TW.ts");
        QTest::newRow("en plurals") << QStringLiteral("imudesk_en.ts");
    }
    void tsFilesAreComplete()
    {
        QFETCH(QString, file);
        QFile f(QDir(translationsDir()).filePath(file));
        QVERIFY2(f.open(QIODevice::ReadOnly), qPrintable(f.fileName()));
        QXmlStreamReader xml(&f);
        int messages = 0;
        QStringList bad;
        QString source;
        while (!xml.atEnd()) {
            xml.readNext();
            if (!xml.isStartElement())
                continue;
            if (xml.name() == QLatin1String("source")) {
                source = xml.readElementText();
            } else if (xml.name() == QLatin1String("translation")) {
                ++messages;
                const QString type = xml.attributes().value(QLatin1String("type")).toString();
                const QString text = xml.readElementText(QXmlStreamReader::IncludeChildElements);
                if (!type.isEmpty())
                    bad << QStringLiteral("%1: %2").arg(type, source.left(80));
                else if (text.trimmed().isEmpty())
                    bad << QStringLiteral("empty: %1").arg(source.left(80));
            }
        }
        QVERIFY2(!xml.hasError(), qPrintable(xml.errorString()));
        QVERIFY(messages > 0);
        QVERIFY2(bad.isEmpty(), qPrintable(QStringLiteral("%1 of %2 entries not done:\n  ").arg(bad.size()).arg(messages) +
                                           bad.join(QStringLiteral("\n  "))));
    }

    void mainWindowUnderZhCN()
    {
        ui::LanguageSwitcher language;
        QString error;
        QVERIFY2(language.setLanguage(QStringLiteral("zh_CN"), QString::fromUtf8(IMUDESK_QM_DIR), &error),
                 qPrintable(error));
        ui::MainWindow window(imudesk::test::builtInFamilies());
        window.resize(1280, 860);
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        verifyTranslated(&window);
        for (QMenu *menu : window.findChildren<QMenu *>())
            verifyTranslated(menu);
    }

    void dialogsUnderZhCN()
    {
        ui::LanguageSwitcher language;
        QString error;
        QVERIFY2(language.setLanguage(QStringLiteral("zh_TW"), QString::fromUtf8(IMUDESK_QM_DIR), &error),
                 qPrintable(error));
        QVERIFY(language.setLanguage(QStringLiteral("zh_CN"), QString::fromUtf8(IMUDESK_QM_DIR), &error));
        ui::PreferencesDialog prefs(ui::Preferences{});
        verifyTranslated(&prefs);
        ui::ModbusConnectDialog modbus;
        verifyTranslated(&modbus);
        ui::CanConnectDialog can;
        verifyTranslated(&can);
        device::DeviceSession session;
        ui::ProfileDialog profiles(session);
        verifyTranslated(&profiles);
        ui::BandwidthCalculator calculator;
        verifyTranslated(&calculator);
        ui::ExportDialog exporter(QStringLiteral("/tmp/x1.imucap"));
        verifyTranslated(&exporter);
        ui::AnalysisWindow analysis;
        verifyTranslated(&analysis);
        ui::FirmwareUpdateDialog firmware(QStringLiteral("/dev/ttyUSB0"), 115200, std::nullopt);
        verifyTranslated(&firmware);
        ui::MainWindow window(imudesk::test::builtInFamilies());
        ui::LiveBridgeDialog bridge(window.liveBridge());
        verifyTranslated(&bridge);
    }

    void wizardsUnderZhCN()
    {
        ui::LanguageSwitcher language;
        QString error;
        QVERIFY2(language.setLanguage(QStringLiteral("zh_CN"), QString::fromUtf8(IMUDESK_QM_DIR), &error),
                 qPrintable(error));
        device::DeviceSession session;
        ui::MagCalibrationWizard mag(session, model::FirmwareVersion{1, 7, 1});
        ui::GyroScaleWizard gyro(session);
        ui::AttitudeResetWizard reset(session);
        for (QWizard *wizard : std::initializer_list<QWizard *>{&mag, &gyro, &reset}) {
            wizard->show();
            // Every page, as the user steps through them.
            for (int id : wizard->pageIds())
                verifyTranslated(wizard->page(id));
            verifyTranslated(wizard);
        }
    }

    void englishPluralForms()
    {
        ui::LanguageSwitcher language;
        QVERIFY(language.setLanguage(QStringLiteral("en"), QString::fromUtf8(IMUDESK_QM_DIR)));
        QCOMPARE(QCoreApplication::translate("imudesk::ui::RawBytesView",
                                             "… %n byte(s) not shown (more arrived than the view holds) …", nullptr, 1),
                 QStringLiteral("… 1 byte not shown (more arrived than the view holds) …"));
        QCOMPARE(QCoreApplication::translate("imudesk::ui::RawBytesView",
                                             "… %n byte(s) not shown (more arrived than the view holds) …", nullptr, 3),
                 QStringLiteral("… 3 bytes not shown (more arrived than the view holds) …"));
    }
};

IMUDESK_TEST_MAIN(TstTranslations)
#include "tst_translations.moc"
