#include "ui/station/station_view.h"

#include "reports/station_report.h"
#include "ui/station/line_database_dialog.h"
#include "ui/station/plan_editor_dialog.h"
#include "core/station/run_folder.h"
#include "ui/station/station_model.h"
#include "core/station/station_runner.h"
#include "ui/station/station_tiles.h"
#include "common/window_helpers.h"

#include <QCloseEvent>
#include <QDialog>
#include <QDesktopServices>
#include <QDir>
#include <QEvent>
#include <QFileDialog>
#include <QFileInfo>
#include <QGridLayout>
#include <QHBoxLayout>
#include <QImageWriter>
#include <QLabel>
#include <QLayout>
#include <QLineEdit>
#include <QListWidget>
#include <QMessageBox>
#include <QPushButton>
#include <QScreen>
#include <QScrollArea>
#include <QSerialPortInfo>
#include <QSettings>
#include <QShortcut>
#include <QStandardPaths>
#include <QTimer>
#include <QUrl>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>

namespace imudesk::ui {

using station::ModuleResult;
using station::StationRunner;
using station::TestPlan;
using station::Verdict;

// ---------------------------------------------------------------- the window

StationView::StationView(QWidget *parent) : QWidget(parent)
{
    setObjectName(QStringLiteral("stationView"));
    // A window of its own, also when the main window owns it.
    setWindowFlag(Qt::Window);
    m_session = new station::StationSession(this);
    m_session->setReportWriter(&writeStationReport);
    m_model = new StationModel(this);

    // Plan: its name and steps, Open…, Edit…, New from example.
    m_planTitle = new QLabel(this);
    m_planName = new ElidedLabel(1, this);
    m_planName->setObjectName(QStringLiteral("planName"));
    m_openPlan = new QPushButton(this);
    m_openPlan->setObjectName(QStringLiteral("openPlan"));
    connect(m_openPlan, &QPushButton::clicked, this, &StationView::choosePlan);
    m_editPlan = new QPushButton(this);
    m_editPlan->setObjectName(QStringLiteral("editPlan"));
    connect(m_editPlan, &QPushButton::clicked, this, [this] { editPlan(); });
    m_examplePlan = new QPushButton(this);
    m_examplePlan->setObjectName(QStringLiteral("examplePlan"));
    connect(m_examplePlan, &QPushButton::clicked, this, &StationView::newFromExample);
    auto *planRow = new QHBoxLayout;
    planRow->addWidget(m_planName, 1);
    planRow->addWidget(m_openPlan);
    planRow->addWidget(m_editPlan);
    planRow->addWidget(m_examplePlan);

    // Ports: a check box per port, flowing in rows; Refresh and the simulated tray beside.
    m_portsTitle = new QLabel(this);
    m_ports = new QListWidget(this);
    m_ports->setObjectName(QStringLiteral("stationPorts"));
    m_ports->setFlow(QListView::LeftToRight);
    m_ports->setWrapping(true);
    m_ports->setResizeMode(QListView::Adjust);
    m_ports->setSpacing(2);
    m_ports->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    m_portsTitle->setBuddy(m_ports);
    connect(m_ports, &QListWidget::itemChanged, this, [this] { updateActions(); });
    m_refreshPorts = new QPushButton(this);
    m_refreshPorts->setObjectName(QStringLiteral("refreshPorts"));
    connect(m_refreshPorts, &QPushButton::clicked, this, &StationView::refreshPorts);
    m_tray = new QPushButton(this);
    m_tray->setObjectName(QStringLiteral("simulatedTray"));
    connect(m_tray, &QPushButton::clicked, this, &StationView::openTrayDialog);
    auto *portButtons = new QVBoxLayout;
    portButtons->setContentsMargins(0, 0, 0, 0);
    portButtons->addWidget(m_refreshPorts);
    portButtons->addWidget(m_tray);
    portButtons->addStretch(1);
    auto *portRow = new QHBoxLayout;
    portRow->addWidget(m_ports, 1);
    portRow->addLayout(portButtons);
    // Two rows of ports, as high as the two buttons beside them.
    m_ports->setFixedHeight(std::max(m_refreshPorts->sizeHint().height() * 2 + 6,
                                     2 * (fontMetrics().height() + 8) + 2 * m_ports->frameWidth()));

    // Report folder.
    m_folderTitle = new QLabel(this);
    m_folder = new QLineEdit(this);
    m_folder->setObjectName(QStringLiteral("reportFolder"));
    m_folderTitle->setBuddy(m_folder);
    connect(m_folder, &QLineEdit::editingFinished, this, [this] { setReportFolder(reportFolder()); });
    m_chooseFolder = new QPushButton(this);
    m_chooseFolder->setObjectName(QStringLiteral("chooseReportFolder"));
    connect(m_chooseFolder, &QPushButton::clicked, this, &StationView::chooseReportFolder);
    m_lineDatabase = new QPushButton(this);
    m_lineDatabase->setObjectName(QStringLiteral("lineDatabaseButton"));
    connect(m_lineDatabase, &QPushButton::clicked, this, &StationView::editLineDatabase);
    m_upload = new LineDatabaseStatus(this);
    connect(m_upload, &LineDatabaseStatus::changed, this, &StationView::updateSummary);
    auto *folderRow = new QHBoxLayout;
    folderRow->addWidget(m_folder, 1);
    folderRow->addWidget(m_chooseFolder);
    folderRow->addWidget(m_lineDatabase);

    // Start, Cancel, Re-run failed; their keys are shortcuts of this window (Ctrl+R here is
    // not the main window's Record).
    m_start = new QPushButton(this);
    m_start->setObjectName(QStringLiteral("startStation"));
    connect(m_start, &QPushButton::clicked, this, [this] { start(); });
    m_cancel = new QPushButton(this);
    m_cancel->setObjectName(QStringLiteral("cancelStation"));
    connect(m_cancel, &QPushButton::clicked, this, &StationView::cancel);
    m_rerun = new QPushButton(this);
    m_rerun->setObjectName(QStringLiteral("rerunFailed"));
    connect(m_rerun, &QPushButton::clicked, this, &StationView::rerunFailed);
    const auto shortcut = [this](const QKeySequence &keys, QPushButton *button) {
        auto *s = new QShortcut(keys, this);
        connect(s, &QShortcut::activated, button, [button] {
            if (button->isEnabled())
                button->click();
        });
    };
    m_openFolder = new QPushButton(this);
    m_openFolder->setObjectName(QStringLiteral("openRunFolder"));
    connect(m_openFolder, &QPushButton::clicked, this, [this] { openRunFolder(); });
    shortcut(QKeySequence(Qt::CTRL | Qt::Key_R), m_start);
    shortcut(QKeySequence(Qt::Key_Escape), m_cancel);
    shortcut(QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_R), m_rerun);
    shortcut(QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_O), m_openFolder);
    auto *runRow = new QHBoxLayout;
    runRow->addWidget(m_start);
    runRow->addWidget(m_cancel);
    runRow->addWidget(m_rerun);
    runRow->addStretch(1);
    runRow->addWidget(m_openFolder);

    auto *top = new QGridLayout;
    top->addWidget(m_planTitle, 0, 0);
    top->addLayout(planRow, 0, 1);
    top->addWidget(m_portsTitle, 1, 0, Qt::AlignTop);
    top->addLayout(portRow, 1, 1);
    top->addWidget(m_folderTitle, 2, 0);
    top->addLayout(folderRow, 2, 1);
    top->addLayout(runRow, 3, 1);
    top->setColumnStretch(1, 1);

    // The summary line, larger, then the tiles.
    m_summary = new ElidedLabel(1, this);
    m_summary->setObjectName(QStringLiteral("stationSummary"));
    QFont summaryFont = m_summary->font();
    summaryFont.setBold(true);
    summaryFont.setPointSizeF(summaryFont.pointSizeF() * 1.15);
    m_summary->setFont(summaryFont);
    m_placeholder = new QLabel(this);
    m_placeholder->setObjectName(QStringLiteral("stationPlaceholder"));
    m_placeholder->setWordWrap(true);
    m_placeholder->setAlignment(Qt::AlignTop | Qt::AlignLeft);
    m_tileArea = new QWidget;
    m_tileArea->setObjectName(QStringLiteral("stationTiles"));
    m_grid = new TileGridLayout(m_tileArea);
    m_scroll = new QScrollArea(this);
    m_scroll->setObjectName(QStringLiteral("stationTileScroll"));
    m_scroll->setFrameShape(QFrame::NoFrame);
    m_scroll->setWidgetResizable(true);
    m_scroll->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    m_scroll->setWidget(m_tileArea);

    auto *layout = new QVBoxLayout(this);
    layout->addLayout(top);
    layout->addWidget(m_summary);
    // The placeholder and the tiles take turns; either takes the height the form leaves (the
    // port list would otherwise stretch into it before a run).
    layout->addWidget(m_placeholder, 1);
    layout->addWidget(m_scroll, 1);

    connect(m_model, &QAbstractItemModel::dataChanged, this,
            [this](const QModelIndex &first, const QModelIndex &last) { updateTiles(first.row(), last.row()); });
    connect(m_model, &QAbstractItemModel::modelReset, this, &StationView::rebuildTiles);
    connect(m_model, &StationModel::refreshed, this, [this] {
        updateSummary();
        updateActions();
    });

    // What the session says: its plan, its tray, its run and the summary line.
    connect(m_session, &station::StationSession::planChanged, this, &StationView::updatePlanLabel);
    connect(m_session, &station::StationSession::trayChanged, this, &StationView::refreshPorts);
    connect(m_session, &station::StationSession::changed, this, [this] {
        updateSummary();
        updateActions();
    });
    connect(m_session, &station::StationSession::runStarted, this,
            [this](const StationRunner *runner) { m_model->setRunner(runner); }); // the tiles follow (modelReset)
    connect(m_session, &station::StationSession::moduleFinished, this, [this] {
        m_model->refresh(); // the tile shows the verdict at once
        showNewReportErrors();
    });
    connect(m_session, &station::StationSession::runFinished, this, [this] {
        m_model->refresh();
        showNewReportErrors();
    });
    connect(m_session, &station::StationSession::workspaceReady, this, &StationView::openWorkspaceRequested);

    m_session->loadSettings();
    m_folder->setText(QDir::toNativeSeparators(m_session->reportFolder()));
    retranslateUi();
    refreshPorts();
    rebuildTiles();
    // The plan used last, when it is still there.
    if (const QString last = m_session->settings().planPath; !last.isEmpty() && QFileInfo::exists(last))
        openPlan(last);
    updatePlanLabel();
    updateActions();

    // At most the screen's work area, at most 1600x900.
    const QSize room = screen() ? screen()->availableGeometry().size() : QSize(1366, 768);
    resize(QSize(1600, 900).boundedTo(room * 95 / 100));
}

StationView::~StationView()
{
    // The tiles let go of the runner, then the session goes (its runner's sessions close before
    // the simulated modules they talk to), telling this half-destroyed window nothing.
    m_model->setRunner(nullptr);
    m_session->disconnect(this);
    delete m_session;
    m_session = nullptr;
}

void StationView::retranslateUi()
{
    setWindowTitle(tr("Production station"));
    m_planTitle->setText(tr("Plan:"));
    m_openPlan->setText(tr("Open…"));
    m_openPlan->setToolTip(tr("Open a test plan (a .json file saved by the plan editor)"));
    m_editPlan->setText(tr("Edit…"));
    m_editPlan->setToolTip(tr("Edit the plan's steps and limits; the next Start uses the saved plan"));
    m_examplePlan->setText(tr("New from example"));
    m_examplePlan->setToolTip(tr("A new plan from the example for HI14 modules, every step with its default "
                                 "limits, opened in the editor (without a firmware image; the profile step is off)"));
    m_portsTitle->setText(tr("Ports:"));
    m_ports->setToolTip(tr("The modules to test: check the port of each"));
    m_refreshPorts->setText(tr("Refresh"));
    m_refreshPorts->setToolTip(tr("Look for serial ports again (after plugging in an adapter)"));
    m_tray->setText(tr("Simulated tray…"));
    m_tray->setToolTip(tr("Start simulated HI14 modules on pseudo-terminals, some of them with faults, to try "
                          "the station without hardware"));
    m_folderTitle->setText(tr("Reports:"));
    m_folder->setToolTip(tr("Each run gets a folder here: the plan, summary.csv and summary.jsonl, a PDF "
                            "report per module and the evidence recordings"));
    m_chooseFolder->setText(tr("Choose…"));
    m_chooseFolder->setToolTip(tr("Choose the folder for the run folders"));
    m_lineDatabase->setText(tr("Line database…"));
    m_lineDatabase->setToolTip(tr("Send every result to the line's PostgreSQL database too, and copy the reports to "
                                  "a shared folder"));
    m_start->setText(tr("Start"));
    m_start->setToolTip(tr("Run the plan on every checked port at once (Ctrl+R)"));
    m_cancel->setText(tr("Cancel"));
    m_cancel->setToolTip(tr("Stop every module's test; the running steps fail as cancelled (Esc)"));
    m_rerun->setText(tr("Re-run failed"));
    m_rerun->setToolTip(tr("Test the modules that failed again, into the same run folder as their next "
                           "attempt (Ctrl+Shift+R)"));
    m_openFolder->setText(tr("Open run folder"));
    m_openFolder->setToolTip(tr("Open the folder of this run: the PDF reports, summary.csv, summary.jsonl and the "
                                "evidence recordings (Ctrl+Shift+O)"));
    m_placeholder->setText(tr("Choose a plan and check the ports of the modules, then press Start (Ctrl+R). "
                              "Each module gets a tile here; click a tile to open that module's workspace."));
    // Port items and tiles carry translated texts too.
    for (int i = 0; i < m_ports->count(); ++i) {
        QListWidgetItem *item = m_ports->item(i);
        const QString port = item->data(Qt::UserRole).toString();
        if (m_session->simulatedPorts().contains(port)) {
            item->setText(tr("%1 (simulated)").arg(port));
            item->setToolTip(m_session->simulatedNote(port));
        }
    }
    updatePlanLabel();
    m_model->refresh(true);
    updateSummary();
}

void StationView::changeEvent(QEvent *event)
{
    if (event->type() == QEvent::LanguageChange && m_start)
        retranslateUi();
    QWidget::changeEvent(event);
}

void StationView::closeEvent(QCloseEvent *event)
{
    // An editor with unsaved changes asks first; answering Cancel keeps both windows open.
    if (m_editor && m_editor->isVisible() && !m_editor->close()) {
        event->ignore();
        return;
    }
    // A run still going is cancelled (each module's report says so), then the simulated
    // modules stop: nothing of the station outlives its window.
    m_session->cancel();
    m_session->stopSimulatedTray();
    QWidget::closeEvent(event);
}

void StationView::showError(const QString &message)
{
    if (m_errorPresenter) {
        m_errorPresenter(message);
        return;
    }
    WindowHelpers::showError(this, m_errorBox, tr("Production station"), message);
}

bool StationView::saveScreenshot(const QString &path, QString *error)
{
    return WindowHelpers::saveScreenshot(this, path, error);
}

bool StationView::openPlan(const QString &path)
{
    QString error;
    if (!m_session->openPlan(path, &error)) {
        showError(error);
        return false;
    }
    return true;
}

void StationView::setPlan(const TestPlan &plan, const QString &path)
{
    m_session->setPlan(plan, path);
}

void StationView::updatePlanLabel()
{
    if (!m_session->hasPlan()) {
        m_planName->setFullText(tr("No plan yet: open one, or start from the example"));
        m_planName->setExtraToolTip(QString());
        return;
    }
    int enabled = 0;
    QStringList steps;
    const TestPlan &plan = m_session->plan();
    const QString &planPath = m_session->planPath();
    for (const station::PlanStep &s : plan.steps) {
        enabled += s.enabled ? 1 : 0;
        steps << (s.enabled ? tr("✓ %1") : tr("✗ %1 (off)")).arg(TestPlan::title(s.kind));
    }
    const QString file = planPath.isEmpty() ? tr("not saved") : QDir::toNativeSeparators(planPath);
    m_planName->setFullText(tr("%1 · %2 of %3 steps · %4")
                                .arg(plan.name.isEmpty() ? tr("(no name)") : plan.name)
                                .arg(enabled)
                                .arg(plan.steps.size())
                                .arg(file));
    m_planName->setExtraToolTip(steps.join(QLatin1Char('\n')));
}

void StationView::choosePlan()
{
    const QString &planPath = m_session->planPath();
    const QString start = planPath.isEmpty() ? QStandardPaths::writableLocation(QStandardPaths::DocumentsLocation)
                                             : QFileInfo(planPath).absolutePath();
    const QString path =
        QFileDialog::getOpenFileName(this, tr("Open test plan"), start, tr("Station plans (*.json);;All files (*)"));
    if (!path.isEmpty())
        openPlan(path);
}

void StationView::newFromExample()
{
    setPlan(demoPlan(), QString());
    if (m_editor)
        m_editor->close();
    editPlan();
}

PlanEditorDialog *StationView::editPlan()
{
    if (m_editor) {
        m_editor->show();
        m_editor->raise();
        m_editor->activateWindow();
        return m_editor;
    }
    auto *editor = new PlanEditorDialog(m_session->hasPlan() ? m_session->plan() : demoPlan(), m_session->planPath(), this);
    editor->setAttribute(Qt::WA_DeleteOnClose);
    connect(editor, &QDialog::finished, editor, &QObject::deleteLater);
    connect(editor, &PlanEditorDialog::saved, this,
            [this](const TestPlan &plan, const QString &path) { setPlan(plan, path); });
    m_editor = editor;
    editor->show();
    return editor;
}

// ---------------------------------------------------------------- ports

void StationView::addPortItem(const QString &port, const QString &text, const QString &toolTip, bool checked)
{
    auto *item = new QListWidgetItem(text, m_ports);
    item->setData(Qt::UserRole, port);
    item->setToolTip(toolTip);
    item->setFlags((item->flags() | Qt::ItemIsUserCheckable) & ~Qt::ItemIsSelectable);
    item->setCheckState(checked ? Qt::Checked : Qt::Unchecked);
}

void StationView::refreshPorts()
{
    const QStringList checked = checkedPorts();
    const QSignalBlocker block(m_ports);
    m_ports->clear();
    for (const QSerialPortInfo &info : QSerialPortInfo::availablePorts()) {
        const QString port = info.systemLocation();
        QStringList tip{port};
        if (!info.description().isEmpty())
            tip << info.description();
        if (!info.manufacturer().isEmpty())
            tip << tr("Made by %1").arg(info.manufacturer());
        if (!info.serialNumber().isEmpty())
            tip << tr("Adapter serial number %1").arg(info.serialNumber());
        addPortItem(port, info.description().isEmpty() ? port : tr("%1 (%2)").arg(port, info.description()),
                    tip.join(QLatin1Char('\n')), checked.contains(port));
    }
    for (const QString &port : m_session->simulatedPorts())
        addPortItem(port, tr("%1 (simulated)").arg(port), m_session->simulatedNote(port), checked.contains(port));
    updateActions();
}

QStringList StationView::checkedPorts() const
{
    QStringList ports;
    for (int i = 0; i < m_ports->count(); ++i)
        if (m_ports->item(i)->checkState() == Qt::Checked)
            ports << m_ports->item(i)->data(Qt::UserRole).toString();
    return ports;
}

void StationView::setPortChecked(const QString &port, bool checked)
{
    for (int i = 0; i < m_ports->count(); ++i)
        if (m_ports->item(i)->data(Qt::UserRole).toString() == port)
            m_ports->item(i)->setCheckState(checked ? Qt::Checked : Qt::Unchecked);
}

// ---------------------------------------------------------------- report folder

QString StationView::reportFolder() const
{
    // What the field says (typed but not yet committed, too), as the next Start uses it.
    const QString dir = QDir::fromNativeSeparators(m_folder->text().trimmed());
    return dir.isEmpty() ? station::StationSettings::defaultReportFolder() : dir;
}

void StationView::setReportFolder(const QString &dir)
{
    m_folder->setText(QDir::toNativeSeparators(dir));
    m_session->setReportFolder(dir);
}

void StationView::editLineDatabase()
{
    const station::StationSettings &settings = m_session->settings();
    auto *dialog = new LineDatabaseDialog(settings.lineDatabase, settings.artifactFolder, this);
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    connect(dialog, &QDialog::accepted, this,
            [this, dialog] { m_session->setLineDatabase(dialog->url(), dialog->artifactFolder()); });
    dialog->open();
}

void StationView::chooseReportFolder()
{
    const QString dir = QFileDialog::getExistingDirectory(this, tr("Folder for the station's reports"), reportFolder());
    if (!dir.isEmpty())
        setReportFolder(dir);
}

// ---------------------------------------------------------------- the run

bool StationView::start()
{
    QString error;
    m_session->setReportFolder(reportFolder()); // a folder typed without leaving the field (Ctrl+R)
    if (!m_session->start(checkedPorts(), &error)) {
        if (!error.isEmpty())
            showError(error);
        return false;
    }
    m_upload->follow(m_session->runner()->uploader());
    m_model->refresh();
    updateSummary();
    updateActions();
    return true;
}

void StationView::showNewReportErrors()
{
    if (const QStringList fresh = m_session->takeNewReportErrors(); !fresh.isEmpty())
        showError(tr("A report could not be written:\n%1").arg(fresh.join(QLatin1Char('\n'))));
}

bool StationView::openUrl(const QString &localPath)
{
    const QUrl url = QUrl::fromLocalFile(localPath);
    if (m_urlOpener ? m_urlOpener(url) : QDesktopServices::openUrl(url))
        return true;
    showError(tr("%1 could not be opened: no application on this computer opens it. Open it from the "
                 "file manager instead.")
                  .arg(QDir::toNativeSeparators(localPath)));
    return false;
}

bool StationView::openReport(int index)
{
    const StationRunner *runner = m_session->runner();
    if (!runner || index < 0 || index >= runner->moduleCount())
        return false;
    const ModuleResult &r = runner->module(index);
    if (r.reportPath.isEmpty() || !QFileInfo::exists(r.reportPath)) {
        showError(r.verdict == Verdict::Running || r.verdict == Verdict::Pending
                      ? tr("The report of %1 is written when its test has ended.").arg(r.port)
                      : tr("%1 has no report: see the run folder's summary, or the message about the report.")
                            .arg(r.port));
        return false;
    }
    return openUrl(r.reportPath);
}

bool StationView::openRunFolder()
{
    if (!m_session->hasRunFolder()) {
        showError(tr("There is no run folder yet: press Start (Ctrl+R) first."));
        return false;
    }
    return openUrl(m_session->runner()->runFolder());
}

QString StationView::summaryText() const
{
    return m_summary->fullText();
}

QWidget *StationView::tile(int index) const
{
    return index >= 0 && index < int(m_tiles.size()) ? m_tiles[size_t(index)] : nullptr;
}

int StationView::tileColumns() const
{
    return m_grid->columns();
}

void StationView::rebuildTiles()
{
    for (StationTile *t : m_tiles)
        delete t; // its layout item goes with it
    m_tiles.clear();
    for (int i = 0; i < m_model->rowCount(); ++i) {
        auto *t = new StationTile(i, m_tileArea);
        t->activated = [this, i] { openModule(i); };
        t->reportRequested = [this, i] { openReport(i); };
        m_grid->addWidget(t);
        m_tiles.push_back(t);
    }
    updateTiles(0, m_model->rowCount() - 1);
    m_placeholder->setVisible(m_tiles.empty());
    m_scroll->setVisible(!m_tiles.empty());
    updateSummary();
}

void StationView::updateTiles(int first, int last)
{
    for (int i = std::max(0, first); i <= last && i < int(m_tiles.size()); ++i) {
        const QModelIndex index = m_model->index(i);
        m_tiles[size_t(i)]->showModule(m_model->result(i), index.data(StationModel::StepRole).toString(),
                                       index.data(StationModel::VerdictTextRole).toString(),
                                       index.data(StationModel::FailureRole).toString(),
                                       index.data(Qt::ToolTipRole).toString());
    }
}

void StationView::updateSummary()
{
    const StationRunner *runner = m_session->runner();
    if (!runner) {
        m_summary->setFullText(m_session->summaryLine());
        m_summary->setExtraToolTip(QString());
        return;
    }
    m_summary->setFullText(m_session->summaryLine() + m_upload->text());
    QString tip = tr("Reports of this run: %1").arg(QDir::toNativeSeparators(runner->runFolder()));
    if (const QString upload = m_upload->toolTip(); !upload.isEmpty())
        tip += QLatin1Char('\n') + upload;
    m_summary->setExtraToolTip(tip);
}

void StationView::updateActions()
{
    if (!m_start)
        return;
    const bool busy = running();
    m_start->setEnabled(!busy && m_session->hasPlan() && !checkedPorts().isEmpty());
    m_cancel->setEnabled(busy);
    m_rerun->setEnabled(m_session->anyFailed());
    m_openFolder->setEnabled(m_session->hasRunFolder());
    m_tray->setEnabled(!busy);
}

} // namespace imudesk::ui
