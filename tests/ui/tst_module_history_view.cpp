// The Results window's history of a module (ui/results/module_history_view.h, issue 53 point
// 17f): a step's detail longer than a column, with line breaks, is cut in the tree's row but
// wholly readable in the Details pane beside it (wrapped, no sideways scrolling), as are a
// measurement's value and limits and an attempt's plan; the pane grows with its splitter.
#include "../common/result_records.h"
#include "../common/test_main.h"
#include "ui/results/module_history_view.h"

#include <QPlainTextEdit>
#include <QScrollBar>
#include <QSplitter>
#include <QTest>
#include <QTreeWidget>

using namespace imudesk;

namespace {

const QString kDetail = QStringLiteral(
    "The module did not answer LOG VERSION within 2 s after the firmware update; the station retried three times "
    "at 115200 and 921600 baud.\nLast reply: 'ERR: busy' (0x45 0x52 0x52). The fixture slot's cable was checked "
    "and the module was power-cycled before the third attempt; see the evidence recording for the bytes.");

QTreeWidgetItem *findItem(QTreeWidget *tree, const QString &startsWith)
{
    for (QTreeWidgetItemIterator it(tree); *it; ++it)
        if ((*it)->text(0).startsWith(startsWith))
            return *it;
    return nullptr;
}

} // namespace

class TstModuleHistoryView : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void stepDetailsWhollyReadable()
    {
        const results::RunRecord run = test::sampleRun();
        results::ModuleRecord m = test::sampleModule(run, QStringLiteral("SN-7"), results::Outcome::Error);
        m.steps[1].detail = kDetail;
        ui::ModuleHistoryView view;
        view.resize(1300, 360);
        view.showHistory(QStringLiteral("SN-7"), {m}, m.uuid);
        view.show();
        QVERIFY(QTest::qWaitForWindowExposed(&view));

        auto *details = view.findChild<QPlainTextEdit *>(QStringLiteral("historyDetails"));
        QVERIFY2(details, "no Details pane");
        QTreeWidgetItem *step = findItem(view.tree(), m.steps[1].name);
        QVERIFY(step);
        // The row shows a line of it, cut; the pane all of it, its line break kept.
        QVERIFY(step->text(1).size() < kDetail.size());
        view.tree()->setCurrentItem(step);
        QVERIFY2(details->toPlainText().contains(kDetail), qPrintable(details->toPlainText()));
        QVERIFY(details->isVisible());
        QVERIFY(details->isReadOnly());
        QCOMPARE(details->lineWrapMode(), QPlainTextEdit::WidgetWidth);
        QVERIFY(!details->horizontalScrollBar()->isVisible());
        QVERIFY2(details->width() >= 250, qPrintable(QString::number(details->width())));
        // Inside the view: nothing of the pane is outside the window.
        const QRect inView(details->mapTo(&view, QPoint(0, 0)), details->size());
        QVERIFY(view.rect().contains(inView));

        // A measurement: its name, value and unit, limits and outcome.
        QTreeWidgetItem *gyro = findItem(view.tree(), QStringLiteral("gyro_std_x"));
        QVERIFY(gyro);
        view.tree()->setCurrentItem(gyro);
        QVERIFY(details->toPlainText().contains(QStringLiteral("gyro_std_x")));
        QVERIFY(details->toPlainText().contains(QStringLiteral("0.05")));
        // The attempt: its plan and station.
        view.tree()->setCurrentItem(view.tree()->topLevelItem(0));
        QVERIFY(details->toPlainText().contains(run.planName));
        QVERIFY(details->toPlainText().contains(run.stationId));

        // The pane can be given more room: the splitter between the tree and it moves.
        const int before = details->width();
        view.splitter()->setSizes({400, 900});
        QCoreApplication::sendPostedEvents(nullptr, QEvent::LayoutRequest);
        QTRY_VERIFY(details->width() > before);
    }
};

IMUDESK_TEST_MAIN(TstModuleHistoryView)
#include "tst_module_history_view.moc"
