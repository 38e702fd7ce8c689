#include "ui/results/results_window.h"

#include "ui/common/window_helpers.h"
#include "ui/results/module_history_view.h"
#include "ui/results/module_table_model.h"
#include "ui/results/results_format.h"
#include "core/results/results_query.h"
#include "ui/results/trend_view.h"
#include "ui/results/yield_view.h"
#include "ui/common/elided_label.h"
#include "core/station/station_settings.h"

#include <QCheckBox>
#include <QCloseEvent>
#include <QComboBox>
#include <QDateEdit>
#include <QDeadlineTimer>
#include <QDesktopServices>
#include <QDir>
#include <QFileDialog>
#include <QFileInfo>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QItemSelectionModel>
#include <QLabel>
#include <QLineEdit>
#include <QProgressBar>
#include <QPushButton>
#include <QScreen>
#include <QSettings>
#include <QShortcut>
#include <QSplitter>
#include <QTabWidget>
#include <QTableView>
#include <QUrl>
#include <QVBoxLayout>

#include <algorithm>
#include <utility>

namespace imudesk::ui {

using results::ModuleRecord;
using results::ResultsStore;

// ---------------------------------------------------------------- reads in the query thread

namespace {

// What a read hands back: its value, or the error (missing: the SQLite file is not there).
template <typename T>
struct ResultsAnswer {
    T value{};
    QString error;
    bool missing = false;
};

// In the query thread: location open in store, opened now unless it is open already. A file
// that is not there is not created (the station makes it with its first run), and a schema is
// never created or migrated from here: this window only reads, and a station's role may not
// create tables on the line's server.
//
// A server that does not answer takes its connect timeout (5 s) to say so; the reads queued
// behind the one that found out (a search posts four) fail at once with the same error instead
// of waiting as long again each. A Search a moment later tries anew.
bool resultsEnsureOpen(ResultsStore &store, const QString &location, QString *error, bool *missing)
{
    struct Failure {
        QString location, error;
        QDeadlineTimer until;
    };
    thread_local Failure failed; // each ResultsQuery has a thread of its own
    if (store.isOpen() && store.location() == location)
        return true;
    store.close();
    if (!ResultsStore::isServerUrl(location) && !QFileInfo::exists(location)) {
        *missing = true;
        return false;
    }
    if (failed.location == location && !failed.until.hasExpired()) {
        *error = failed.error;
        return false;
    }
    if (store.open(location, error, false))
        return true;
    failed = {location, *error, QDeadlineTimer(2000)};
    return false;
}

// A read of location: the store opened there first, then fn(store, &error).
template <typename Fn>
auto resultsRead(const QString &location, Fn fn)
{
    using Value = decltype(fn(std::declval<ResultsStore &>(), static_cast<QString *>(nullptr)));
    return [location, fn](ResultsStore &store) {
        ResultsAnswer<Value> a;
        if (!resultsEnsureOpen(store, location, &a.error, &a.missing))
            return a;
        a.value = fn(store, &a.error);
        // A server that went away leaves a dead connection: the next read connects anew.
        if (!a.error.isEmpty())
            store.close();
        return a;
    };
}

} // namespace

// ---------------------------------------------------------------- settings

void ResultsWindowSettings::load(QSettings &settings)
{
    geometry = settings.value(QLatin1String(kGeometryKey)).toByteArray();
    splitter = settings.value(QLatin1String(kSplitterKey)).toByteArray();
}

void ResultsWindowSettings::save(QSettings &settings) const
{
    settings.setValue(QLatin1String(kGeometryKey), geometry);
    settings.setValue(QLatin1String(kSplitterKey), splitter);
}

QString ResultsWindow::stationDatabase()
{
    QSettings store;
    station::StationSettings s;
    s.load(store);
    return s.resultsDatabase();
}

// ---------------------------------------------------------------- the window

ResultsWindow::ResultsWindow(QWidget *parent) : QWidget(parent)
{
    setObjectName(QStringLiteral("resultsWindow"));
    setWindowFlag(Qt::Window); // a window of its own, also when the main window owns it
    m_query = new ResultsQuery(this);
    connect(m_query, &ResultsQuery::busyChanged, this, &ResultsWindow::updateStatus);

    // Where the window reads, and Open… for another file.
    m_sourceTitle = new QLabel(this);
    m_source = new ElidedLabel(1, this);
    m_source->setObjectName(QStringLiteral("resultsSource"));
    m_openFile = new QPushButton(this);
    m_openFile->setObjectName(QStringLiteral("openResultsFile"));
    connect(m_openFile, &QPushButton::clicked, this, &ResultsWindow::chooseFile);
    auto *sourceRow = new QHBoxLayout;
    sourceRow->addWidget(m_sourceTitle);
    sourceRow->addWidget(m_source, 1);
    sourceRow->addWidget(m_openFile);

    // The filter row; Enter in any of its fields searches.
    m_filterRow = new QWidget(this);
    m_filterRow->setObjectName(QStringLiteral("resultsFilter"));
    m_serialTitle = new QLabel(m_filterRow);
    m_serial = new QLineEdit(m_filterRow);
    m_serial->setObjectName(QStringLiteral("filterSerial"));
    m_serial->setClearButtonEnabled(true);
    // Enter in the field (the row's shortcut below takes Enter first when the field has focus;
    // this covers a key that reaches the field itself).
    connect(m_serial, &QLineEdit::returnPressed, this, &ResultsWindow::search);
    m_serialTitle->setBuddy(m_serial);
    m_planTitle = new QLabel(m_filterRow);
    m_plan = new QComboBox(m_filterRow);
    m_plan->setObjectName(QStringLiteral("filterPlan"));
    m_stationTitle = new QLabel(m_filterRow);
    m_station = new QComboBox(m_filterRow);
    m_station->setObjectName(QStringLiteral("filterStation"));
    for (QComboBox *combo : {m_plan, m_station}) {
        // A plan's name may be of any length: the combo box shows what fits, the tooltip all.
        combo->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
        combo->setMinimumContentsLength(combo == m_plan ? 16 : 10);
        combo->addItem(QString(), QString()); // Any
        connect(combo, &QComboBox::activated, this, [this, combo] {
            combo->setToolTip(combo->currentData(Qt::ToolTipRole).toString());
            search();
        });
    }
    m_planTitle->setBuddy(m_plan);
    m_stationTitle->setBuddy(m_station);
    m_fromCheck = new QCheckBox(m_filterRow);
    m_fromCheck->setObjectName(QStringLiteral("filterFromOn"));
    m_from = new QDateEdit(QDate::currentDate().addDays(-30), m_filterRow);
    m_from->setObjectName(QStringLiteral("filterFrom"));
    m_toCheck = new QCheckBox(m_filterRow);
    m_toCheck->setObjectName(QStringLiteral("filterToOn"));
    m_to = new QDateEdit(QDate::currentDate(), m_filterRow);
    m_to->setObjectName(QStringLiteral("filterTo"));
    for (auto [check, date] : {std::pair{m_fromCheck, m_from}, std::pair{m_toCheck, m_to}}) {
        date->setCalendarPopup(true);
        date->setDisplayFormat(QStringLiteral("yyyy-MM-dd"));
        date->setEnabled(false);
        connect(check, &QCheckBox::toggled, date, &QWidget::setEnabled);
    }
    m_search = new QPushButton(m_filterRow);
    m_search->setObjectName(QStringLiteral("searchButton"));
    connect(m_search, &QPushButton::clicked, this, &ResultsWindow::search);
    for (const auto key : {Qt::Key_Return, Qt::Key_Enter}) {
        auto *enter = new QShortcut(QKeySequence(key), m_filterRow);
        enter->setContext(Qt::WidgetWithChildrenShortcut);
        connect(enter, &QShortcut::activated, this, &ResultsWindow::search);
    }
    auto *filter = new QHBoxLayout(m_filterRow);
    filter->setContentsMargins(0, 0, 0, 0);
    filter->addWidget(m_serialTitle);
    filter->addWidget(m_serial, 1);
    filter->addSpacing(6);
    filter->addWidget(m_planTitle);
    filter->addWidget(m_plan, 2);
    filter->addSpacing(6);
    filter->addWidget(m_stationTitle);
    filter->addWidget(m_station, 1);
    filter->addSpacing(6);
    filter->addWidget(m_fromCheck);
    filter->addWidget(m_from);
    filter->addWidget(m_toCheck);
    filter->addWidget(m_to);
    filter->addSpacing(6);
    filter->addWidget(m_search);

    // A busy bar while a read is under way, what the last search found, and a problem in red.
    m_busy = new QProgressBar(this);
    m_busy->setObjectName(QStringLiteral("resultsBusy"));
    m_busy->setRange(0, 0);
    m_busy->setTextVisible(false);
    m_busy->setFixedWidth(120);
    QSizePolicy keep = m_busy->sizePolicy();
    keep.setRetainSizeWhenHidden(true); // the status line does not jump
    m_busy->setSizePolicy(keep);
    m_status = new ElidedLabel(1, this);
    m_status->setObjectName(QStringLiteral("resultsStatus"));
    auto *statusRow = new QHBoxLayout;
    statusRow->addWidget(m_status, 1);
    statusRow->addWidget(m_busy);
    m_problemLabel = new QLabel(this);
    m_problemLabel->setObjectName(QStringLiteral("resultsProblem"));
    m_problemLabel->setWordWrap(true);
    m_problemLabel->setTextFormat(Qt::PlainText); // an error may hold any text
    m_problemLabel->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_problemLabel->setStyleSheet(QStringLiteral("color: #c62828;"));
    m_problemLabel->hide();

    // Modules: the table, and the selected serial number's history below it.
    m_model = new ModuleTableModel(this);
    m_table = new QTableView(this);
    m_table->setObjectName(QStringLiteral("modulesTable"));
    m_table->setModel(m_model);
    m_table->setSelectionBehavior(QAbstractItemView::SelectRows);
    m_table->setSelectionMode(QAbstractItemView::SingleSelection);
    m_table->setEditTriggers(QAbstractItemView::NoEditTriggers);
    m_table->setWordWrap(false);
    m_table->setTextElideMode(Qt::ElideRight);
    m_table->verticalHeader()->hide();
    // The plan takes the room left: a long name is elided, and the attempt stays by the others.
    m_table->horizontalHeader()->setSectionResizeMode(ModuleTableModel::Plan, QHeaderView::Stretch);
    m_table->horizontalHeader()->setResizeContentsPrecision(200);
    connect(m_table->selectionModel(), &QItemSelectionModel::currentRowChanged, this,
            &ResultsWindow::showSelectedHistory);
    m_history = new ModuleHistoryView(this);
    m_history->setObjectName(QStringLiteral("moduleHistory"));
    connect(m_history, &ModuleHistoryView::openRequested, this, &ResultsWindow::openArtifact);
    m_modulesSplit = new QSplitter(Qt::Vertical, this);
    m_modulesSplit->setObjectName(QStringLiteral("modulesSplitter"));
    m_modulesSplit->setChildrenCollapsible(false);
    m_modulesSplit->addWidget(m_table);
    m_modulesSplit->addWidget(m_history);
    m_modulesSplit->setStretchFactor(0, 1);
    m_modulesSplit->setStretchFactor(1, 1);

    m_yield = new YieldView(this);
    m_yield->setObjectName(QStringLiteral("yieldView"));
    m_trend = new TrendView(this);
    m_trend->setObjectName(QStringLiteral("trendView"));
    connect(m_trend, &TrendView::measurementChosen, this, &ResultsWindow::refreshTrend);
    m_tabs = new QTabWidget(this);
    m_tabs->setObjectName(QStringLiteral("resultsTabs"));
    m_tabs->addTab(m_modulesSplit, QString());
    m_tabs->addTab(m_yield, QString());
    m_tabs->addTab(m_trend, QString());

    auto *layout = new QVBoxLayout(this);
    layout->addLayout(sourceRow);
    layout->addWidget(m_filterRow);
    layout->addLayout(statusRow);
    layout->addWidget(m_problemLabel);
    layout->addWidget(m_tabs, 1);

    retranslateUi();
    m_table->resizeColumnsToContents();

    ResultsWindowSettings saved;
    {
        QSettings store;
        saved.load(store);
    }
    if (saved.geometry.isEmpty() || !restoreGeometry(saved.geometry)) {
        const QSize room = screen() ? screen()->availableGeometry().size() : QSize(1366, 768);
        resize(QSize(1280, 800).boundedTo(room * 95 / 100));
    }
    if (!saved.splitter.isEmpty())
        m_modulesSplit->restoreState(saved.splitter);
}

ResultsWindow::~ResultsWindow() = default; // m_query (a child) waits for a read under way

void ResultsWindow::retranslateUi()
{
    setWindowTitle(tr("Results"));
    m_sourceTitle->setText(tr("Database:"));
    m_openFile->setText(tr("Open…"));
    m_openFile->setToolTip(tr("Read another results file (an SQLite file a station wrote: results.sqlite)"));
    m_serialTitle->setText(tr("Serial:"));
    m_serial->setPlaceholderText(tr("part of a serial number"));
    m_serial->setToolTip(tr("Modules whose serial number contains this text, as it is written"));
    m_planTitle->setText(tr("Plan:"));
    m_stationTitle->setText(tr("Station:"));
    for (QComboBox *combo : {m_plan, m_station})
        combo->setItemText(0, tr("Any"));
    m_fromCheck->setText(tr("From"));
    m_fromCheck->setToolTip(tr("Only modules started on this day or later (also for the yield and the trend)"));
    m_toCheck->setText(tr("To"));
    m_toCheck->setToolTip(tr("Only modules started on this day or earlier (also for the trend)"));
    m_search->setText(tr("Search"));
    m_search->setToolTip(tr("List the modules that match the filter, and count the yield of its plan (Enter)"));
    m_busy->setToolTip(tr("Reading the results database…"));
    m_tabs->setTabText(ModulesTab, tr("Modules"));
    m_tabs->setTabToolTip(ModulesTab, tr("The modules found; select one to see every attempt of its serial number"));
    m_tabs->setTabText(YieldTab, tr("Yield"));
    m_tabs->setTabToolTip(YieldTab, tr("Pass, fail and yield of the chosen plan, per firmware and fixture slot"));
    m_tabs->setTabText(TrendTab, tr("Trend"));
    m_tabs->setTabToolTip(TrendTab, tr("One measurement of the chosen plan over time, with its limits and Cpk"));
    m_model->retranslate();
    updateSource();
    updateStatus();
    if (m_plan->currentIndex() <= 0) {
        m_yield->showMessage(tr("Choose a plan in the filter above: the yield is counted per plan."));
        m_trend->showMessage(tr("Choose a plan in the filter above to see its measurements over time."));
    }
}

void ResultsWindow::changeEvent(QEvent *event)
{
    if (event->type() == QEvent::LanguageChange && m_tabs)
        retranslateUi();
    QWidget::changeEvent(event);
}

void ResultsWindow::closeEvent(QCloseEvent *event)
{
    if (m_remember) {
        ResultsWindowSettings s;
        s.geometry = saveGeometry();
        s.splitter = m_modulesSplit->saveState();
        QSettings store;
        s.save(store);
    }
    QWidget::closeEvent(event);
}

bool ResultsWindow::saveScreenshot(const QString &path, QString *error)
{
    return WindowHelpers::saveScreenshot(this, path, error);
}

// ---------------------------------------------------------------- where it reads

void ResultsWindow::openLocation(const QString &location, bool chosen)
{
    m_query->dropAll(); // answers about the database before are no longer wanted
    m_location = location;
    m_chosen = chosen;
    m_found = -1;
    m_model->setModules({});
    m_history->showMessage(QString());
    showProblem(QString());
    updateSource();
    search();
}

void ResultsWindow::chooseFile()
{
    const QString start = ResultsStore::isServerUrl(m_location) ? QString() : QFileInfo(m_location).absolutePath();
    const QString path = QFileDialog::getOpenFileName(this, tr("Open a results database"), start,
                                                      tr("Results databases (*.sqlite *.db);;All files (*)"));
    if (!path.isEmpty())
        openLocation(path, true);
}

void ResultsWindow::updateSource()
{
    if (m_location.isEmpty()) {
        m_source->setFullText(tr("none"));
        return;
    }
    if (ResultsStore::isServerUrl(m_location))
        m_source->setFullText(tr("the line database, %1").arg(ResultsStore::displayLocation(m_location)));
    else if (m_chosen)
        m_source->setFullText(tr("the file %1").arg(QDir::toNativeSeparators(m_location)));
    else
        m_source->setFullText(tr("this station's database, %1").arg(QDir::toNativeSeparators(m_location)));
}

// ---------------------------------------------------------------- state and problems

bool ResultsWindow::busy() const
{
    return m_query->busy();
}

QString ResultsWindow::problem() const
{
    return m_problem;
}

void ResultsWindow::updateStatus()
{
    const bool reading = m_query->busy();
    m_busy->setVisible(reading);
    if (reading)
        m_status->setFullText(tr("Reading the results database…"));
    else if (m_found < 0)
        m_status->setFullText(QString());
    else if (m_limited)
        m_status->setFullText(tr("The newest %n module(s) found; there are more: narrow the filter to see them.", nullptr,
                                 m_found));
    else
        m_status->setFullText(tr("%n module(s) found.", nullptr, m_found));
}

void ResultsWindow::showProblem(const QString &text)
{
    m_problem = text;
    m_problemLabel->setText(text);
    m_problemLabel->setVisible(!text.isEmpty());
}

void ResultsWindow::readFailed(const QString &error)
{
    const QString where = ResultsStore::displayLocation(m_location);
    if (ResultsStore::isServerUrl(m_location))
        showProblem(tr("The line database %1 could not be read: %2\nCheck the network and that the server runs, "
                       "then press Search to try again; or read this station's own file with Open….")
                        .arg(where, error.trimmed()));
    else
        showProblem(tr("%1 could not be read: %2\nIs it a results database that ImuDesk wrote? Choose another "
                       "file with Open….")
                        .arg(QDir::toNativeSeparators(where), error.trimmed()));
}

// ---------------------------------------------------------------- reads

void ResultsWindow::fillCombo(QComboBox *combo, const QStringList &values)
{
    const QString kept = combo->currentData().toString();
    while (combo->count() > 1)
        combo->removeItem(1);
    for (const QString &v : values)
        if (!v.isEmpty()) // the empty name is "Any"'s
            ResultsFormat::addComboItem(combo, v, v);
    const int at = combo->findData(kept);
    combo->setCurrentIndex(at >= 0 ? at : 0);
    combo->setToolTip(combo->currentData(Qt::ToolTipRole).toString());
}

void ResultsWindow::refreshLists()
{
    if (m_location.isEmpty())
        return;
    m_query->ask(ListsChannel, resultsRead(m_location, [](ResultsStore &store, QString *) {
                     return std::pair{store.planNames(), store.stationIds()};
                 }),
                 [this](const ResultsAnswer<std::pair<QStringList, QStringList>> &a) {
                     if (a.missing || !a.error.isEmpty())
                         return; // the search's answer says so
                     fillCombo(m_plan, a.value.first);
                     fillCombo(m_station, a.value.second);
                 });
}

QString ResultsWindow::chosenPlan() const
{
    return m_plan->currentData().toString();
}

QDateTime ResultsWindow::fromTime() const
{
    return m_fromCheck->isChecked() ? QDateTime(m_from->date(), QTime(0, 0)) : QDateTime();
}

QDateTime ResultsWindow::toTime() const
{
    return m_toCheck->isChecked() ? QDateTime(m_to->date().addDays(1), QTime(0, 0)).addMSecs(-1) : QDateTime();
}

ResultsStore::Filter ResultsWindow::filter() const
{
    ResultsStore::Filter f;
    f.serial = m_serial->text().trimmed();
    f.plan = chosenPlan();
    f.station = m_station->currentData().toString();
    f.from = fromTime();
    f.to = toTime();
    return f;
}

void ResultsWindow::search()
{
    if (m_location.isEmpty())
        return;
    const ResultsStore::Filter f = filter();
    m_query->ask(
        SearchChannel, resultsRead(m_location, [f](ResultsStore &store, QString *error) { return store.search(f, error); }),
        [this, limit = f.limit](const ResultsAnswer<std::vector<ModuleRecord>> &a) {
            if (a.missing) {
                m_found = -1;
                m_model->setModules({});
                showProblem(tr("There are no results in %1 yet: the station writes this file with its first run. "
                               "Open another file with Open…, or set the line database in the station window.")
                                .arg(QDir::toNativeSeparators(m_location)));
                updateStatus();
                return;
            }
            if (!a.error.isEmpty()) {
                readFailed(a.error);
                return;
            }
            showProblem(QString());
            const QModelIndex current = m_table->currentIndex();
            const QString selected = current.isValid() ? current.data(ModuleTableModel::UuidRole).toString() : QString();
            m_model->setModules(a.value);
            m_found = int(a.value.size());
            m_limited = m_found >= limit;
            updateStatus();
            // Columns as wide as their contents, but none wider than a cap: a 10 kB plan name is
            // elided in its cell (whole in the tooltip) and the other columns stay in view.
            m_table->resizeColumnsToContents();
            const int cap = fontMetrics().averageCharWidth() * 30;
            for (int c = 0; c < ModuleTableModel::ColumnCount; ++c)
                m_table->setColumnWidth(c, std::min(m_table->columnWidth(c), cap));
            const int row = m_model->rowOf(selected);
            if (row >= 0)
                m_table->selectRow(row);
            else
                m_history->showMessage(QString());
        });
    refreshLists(); // a run since the last search may have brought a plan or a station
    refreshYield();
    refreshMeasurements();
}

void ResultsWindow::showSelectedHistory()
{
    const QModelIndex current = m_table->currentIndex();
    if (!current.isValid()) {
        m_history->showMessage(QString());
        return;
    }
    const QString serial = current.data(ModuleTableModel::SerialRole).toString();
    const QString uuid = current.data(ModuleTableModel::UuidRole).toString();
    m_history->showMessage(tr("Reading the history of %1…").arg(serial));
    m_query->ask(HistoryChannel,
                 resultsRead(m_location, [serial](ResultsStore &store, QString *error) { return store.history(serial, error); }),
                 [this, serial, uuid](const ResultsAnswer<std::vector<ModuleRecord>> &a) {
                     if (!a.error.isEmpty() || a.missing) {
                         m_history->showMessage(QString());
                         if (!a.missing)
                             readFailed(a.error);
                         return;
                     }
                     m_history->showHistory(serial, a.value, uuid);
                 });
}

void ResultsWindow::refreshYield()
{
    const QString plan = chosenPlan();
    if (plan.isEmpty()) {
        m_yield->showMessage(tr("Choose a plan in the filter above: the yield is counted per plan."));
        return;
    }
    const QDateTime since = fromTime();
    m_query->ask(YieldChannel,
                 resultsRead(m_location, [plan, since](ResultsStore &store, QString *error) { return store.yield(plan, since, error); }),
                 [this, plan, since](const ResultsAnswer<ResultsStore::Yield> &a) {
                     if (!a.error.isEmpty() || a.missing) {
                         m_yield->showMessage(QString());
                         return; // the search's answer says why
                     }
                     m_yield->showYield(plan, since, a.value);
                 });
}

void ResultsWindow::refreshMeasurements()
{
    const QString plan = chosenPlan();
    if (plan.isEmpty()) {
        m_trend->setMeasurements({});
        m_trend->showMessage(tr("Choose a plan in the filter above to see its measurements over time."));
        return;
    }
    m_query->ask(MeasurementsChannel,
                 resultsRead(m_location, [plan](ResultsStore &store, QString *) { return store.measurementNames(plan); }),
                 [this](const ResultsAnswer<QStringList> &a) {
                     if (!a.error.isEmpty() || a.missing)
                         return;
                     m_trend->setMeasurements(a.value);
                     refreshTrend();
                 });
}

void ResultsWindow::refreshTrend()
{
    const QString plan = chosenPlan();
    const QString measurement = m_trend->measurement();
    if (plan.isEmpty())
        return; // refreshMeasurements said so
    if (measurement.isEmpty()) {
        m_trend->showMessage(tr("The plan's modules have no measurements here."));
        return;
    }
    const QDateTime from = fromTime(), to = toTime();
    using Series = std::pair<std::vector<ResultsStore::Point>, ResultsStore::Capability>;
    m_query->ask(TrendChannel,
                 resultsRead(m_location,
                             [plan, measurement, from, to](ResultsStore &store, QString *error) {
                                 Series s;
                                 s.first = store.series(plan, measurement, from, to, error);
                                 s.second = ResultsStore::capability(s.first);
                                 return s;
                             }),
                 [this, measurement](const ResultsAnswer<Series> &a) {
                     if (!a.error.isEmpty() || a.missing) {
                         m_trend->showMessage(QString());
                         return;
                     }
                     m_trend->showSeries(measurement, a.value.first, a.value.second);
                 });
}

// ---------------------------------------------------------------- files

void ResultsWindow::openArtifact(const QString &location)
{
    if (location.isEmpty() || !QFileInfo::exists(location)) {
        showProblem(tr("%1 is not on this computer (it may be on the station that tested the module, or moved). "
                       "Look for it in that station's report folder or in the shared artifact folder.")
                        .arg(QDir::toNativeSeparators(location)));
        return;
    }
    const QUrl url = QUrl::fromLocalFile(location);
    if (m_urlOpener ? m_urlOpener(url) : QDesktopServices::openUrl(url))
        return;
    showProblem(tr("%1 could not be opened: no application on this computer opens it. Open it from the file manager "
                   "instead.")
                    .arg(QDir::toNativeSeparators(location)));
}

} // namespace imudesk::ui
