// Preferences: stored under versioned keys, validated on load, edited in the dialog and
// applied to the live views (units, attitude frame, refresh clock, history, reconnect).
#include "../common/ui_families.h"
#include "attitude/attitude_widget.h"
#include "charts/chart_panel.h"
#include "charts/chart_view.h"
#include "workspace/device_workspace.h"
#include "workspace/main_window.h"
#include "itemmodels/latest_values_model.h"
#include "workspace/preferences.h"
#include "workspace/preferences_dialog.h"
#include "recording/recording_controls.h"
#include "../common/test_main.h"

#include <QApplication>
#include <QCheckBox>
#include <QComboBox>
#include <QDateTime>
#include <QLabel>
#include <QLineEdit>
#include <QSettings>
#include <QSignalSpy>
#include <QSpinBox>
#include <QTemporaryDir>
#include <QTest>

using namespace imudesk;
using ui::Preferences;

class TstPreferences : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void roundTripAndValidation()
    {
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        const QString path = dir.filePath(QStringLiteral("prefs.ini"));
        Preferences p;
        p.language = QStringLiteral("zh_TW");
        p.units = {model::AccelUnit::MetresPerSecondSquared, model::RateUnit::RadiansPerSecond};
        p.frame = Preferences::Frame::Ned;
        p.refreshHz = 20;
        p.historyMinutes = 3;
        p.recordingFolder = dir.path();
        p.recordingPattern = QStringLiteral("run-{serial}-{date}.imucap");
        p.autoReconnect = false;
        {
            QSettings s(path, QSettings::IniFormat);
            p.save(s);
        }
        Preferences back;
        {
            QSettings s(path, QSettings::IniFormat);
            QCOMPARE(s.value(QLatin1String(Preferences::kFrameKey)).toString(), QStringLiteral("NED"));
            back.load(s);
        }
        QVERIFY(back == p);

        // Nonsense falls back to the defaults, value by value.
        {
            QSettings s(path, QSettings::IniFormat);
            s.setValue(QLatin1String(Preferences::kRefreshKey), 500);
            s.setValue(QLatin1String(Preferences::kHistoryKey), 0);
            s.setValue(QLatin1String(Preferences::kLanguageKey), QStringLiteral("xx"));
        }
        QSettings s(path, QSettings::IniFormat);
        back.load(s);
        const Preferences defaults;
        QCOMPARE(back.refreshHz, defaults.refreshHz);
        QCOMPARE(back.historyMinutes, defaults.historyMinutes);
        QCOMPARE(back.language, QString());
        QVERIFY(back.units == p.units); // the valid values stay
    }

    void patternExampleIsTheRealName()
    {
        // The dialog shows the name the recording controls will give (one expansion, not two).
        Preferences p;
        p.recordingPattern = QStringLiteral("{product}-{serial}");
        ui::PreferencesDialog dialog(p);
        QCOMPARE(dialog.patternExample()->text(), QStringLiteral("HI14R3-2181B60A.imucap"));
        const QDateTime when(QDate(2026, 11, 21), QTime(15, 4, 5));
        QCOMPARE(ui::RecordingControls::expandPattern(Preferences{}.recordingPattern, QStringLiteral("HI14R3"),
                                                      QStringLiteral("ABC"), when),
                 QStringLiteral("HI14R3-20261121-150405.imucap"));
        // Nothing leaves the chosen folder.
        const QString name = ui::RecordingControls::expandPattern(QStringLiteral("../../etc/{product}/x"),
                                                                  QStringLiteral("a/b"), {}, when);
        QVERIFY2(!name.contains(QLatin1Char('/')) && !name.contains(QLatin1Char('\\')), qPrintable(name));
        // A serial from the device with control characters, a leading dot and no end.
        const QString hostile = ui::RecordingControls::expandPattern(QStringLiteral("{serial}"),
                                                                     {}, QStringLiteral("..\n\x01%1").arg(QString(400, u'x')), when);
        QVERIFY2(!hostile.startsWith(QLatin1Char('.')), qPrintable(hostile));
        QVERIFY2(hostile.size() <= 200 + 7 && hostile.endsWith(QLatin1String(".imucap")), qPrintable(hostile));
        for (QChar c : hostile)
            QVERIFY2(c.unicode() >= 0x20, qPrintable(hostile));
    }

    void dialogEditsEveryValue()
    {
        Preferences p;
        ui::PreferencesDialog dialog(p);
        dialog.languageCombo()->setCurrentIndex(dialog.languageCombo()->findData(QStringLiteral("zh_CN")));
        dialog.accelCombo()->setCurrentIndex(1);
        dialog.rateCombo()->setCurrentIndex(1);
        dialog.frameCombo()->setCurrentIndex(1);
        dialog.refreshSpin()->setValue(60);
        dialog.historySpin()->setValue(2);
        dialog.folderEdit()->setText(QStringLiteral("/tmp/rec"));
        dialog.patternEdit()->setText(QStringLiteral("{device}.imucap"));
        dialog.reconnectCheck()->setChecked(false);
        const Preferences out = dialog.preferences();
        QCOMPARE(out.language, QStringLiteral("zh_CN"));
        QVERIFY(out.units.accel == model::AccelUnit::MetresPerSecondSquared);
        QVERIFY(out.units.rate == model::RateUnit::RadiansPerSecond);
        QVERIFY(out.frame == Preferences::Frame::Ned);
        QCOMPARE(out.refreshHz, 60);
        QCOMPARE(out.refreshIntervalMs(), 16);
        QCOMPARE(out.historyMinutes, 2);
        QCOMPARE(out.recordingFolder, QStringLiteral("/tmp/rec"));
        QCOMPARE(out.recordingPattern, QStringLiteral("{device}.imucap"));
        QVERIFY(!out.autoReconnect);
        // Spin boxes refuse what the views cannot do.
        dialog.refreshSpin()->setValue(1000);
        QCOMPARE(dialog.preferences().refreshHz, Preferences::kMaxRefreshHz);
    }

    void appliedToTheViews()
    {
        ui::DeviceWorkspace ws;
        Preferences p;
        p.units = {model::AccelUnit::MetresPerSecondSquared, model::RateUnit::RadiansPerSecond};
        p.frame = Preferences::Frame::Ned;
        p.refreshHz = 20;
        p.historyMinutes = 2;
        ws.applyPreferences(p);
        QCOMPARE(ws.attitudeWidget()->displayFrame(), ui::AttitudeWidget::DisplayFrame::Ned);
        QCOMPARE(ws.chartPanel()->history().maxDuration(), 120.0);
        ui::ChartView *acc = ws.chartPanel()->chart(ui::ChartKind::Accelerometer);
        ui::ChartView *gyr = ws.chartPanel()->chart(ui::ChartKind::Gyroscope);
        QCOMPARE(acc->shownUnit(), QStringLiteral("m/s²"));
        QCOMPARE(gyr->shownUnit(), QStringLiteral("rad/s"));
        QVERIFY(std::abs(acc->unitFactor() - 9.8) < 1e-12);

        // A sample of 1 G and 90 deg/s reads 9.8 m/s² and 1.5708 rad/s in the values table.
        models::LatestValuesModel *values = ws.valuesModel();
        model::Sample s;
        s.fields = model::FieldAcc | model::FieldGyr;
        s.acc = {1.0, 0.0, 0.0};
        s.gyr = {90.0, 0.0, 0.0};
        values->refresh(s);
        QCOMPARE(values->valueText(models::LatestValuesModel::AccX), QStringLiteral("9.8000"));
        QCOMPARE(values->valueText(models::LatestValuesModel::GyrX), QStringLiteral("1.57080"));
        QCOMPARE(values->index(models::LatestValuesModel::AccX, models::LatestValuesModel::UnitColumn).data().toString(),
                 QStringLiteral("m/s²"));
        // And back.
        ws.applyPreferences(Preferences{});
        QCOMPARE(values->valueText(models::LatestValuesModel::AccX), QStringLiteral("1.0000"));
        QCOMPARE(acc->shownUnit(), QStringLiteral("G"));
    }

    void mainWindowAppliesToNewTabs()
    {
        ui::MainWindow window(imudesk::test::builtInFamilies());
        Preferences p;
        p.frame = Preferences::Frame::Ned;
        window.setPreferences(p);
        ui::DeviceWorkspace *second = window.newWorkspace();
        QCOMPARE(second->attitudeWidget()->displayFrame(), ui::AttitudeWidget::DisplayFrame::Ned);
        ui::PreferencesDialog *dialog = window.openPreferences();
        QVERIFY(dialog);
        QSignalSpy changed(&window, &ui::MainWindow::preferencesChanged);
        dialog->frameCombo()->setCurrentIndex(0);
        dialog->accept();
        QCOMPARE(changed.count(), 1);
        QCOMPARE(window.workspace(0)->attitudeWidget()->displayFrame(), ui::AttitudeWidget::DisplayFrame::Enu);
        QCOMPARE(second->attitudeWidget()->displayFrame(), ui::AttitudeWidget::DisplayFrame::Enu);
    }
};

IMUDESK_TEST_MAIN(TstPreferences)
#include "tst_preferences.moc"
