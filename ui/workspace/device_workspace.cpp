#include "workspace/device_workspace.h"
#include "verify/live_reference.h"

#include "device/session.h"

#include "attitude/attitude_widget.h"
#include "model/attitude.h"
#include "configuration/config_panel.h"
#include "recording/recording_controls.h"
#include "charts/chart_panel.h"
#include "workspace/command_log_widget.h"
#include "workspace/console_widget.h"
#include "workspace/raw_bytes_view.h"
#include "itemmodels/clock_stats_model.h"
#include "itemmodels/latest_values_model.h"
#include "sim/pty_simulator.h"
#include "workspace/status_flags_widget.h"

#include <QAction>
#include <QDockWidget>
#include <QEvent>
#include <QHBoxLayout>
#include <QKeySequence>
#include <QHeaderView>
#include <QLabel>
#include <QStatusBar>
#include <QStyledItemDelegate>
#include <QTableView>
#include <QVBoxLayout>

#include <utility>

namespace imudesk::ui {

using device::SessionState;

namespace {

// The rows of the values table. Before any data: the core quantities. Once data arrived: the
// fields this link has sent (a compass sends no quaternion, a HI83 sends its position). The
// status word and the frame type stay in the status bar (the flags coloured by meaning, the
// frame type with its rate), so the table fits without a scroll bar beside the 3D attitude.
bool rowInTable(models::LatestValuesModel::Row row, bool everSeen, bool anyData, bool detailsShown = false)
{
    using Model = models::LatestValuesModel;
    if (row == Model::StatusFlags || row == Model::FrameType || Model::isDetailRow(row)
        || (detailsShown && Model::isSecondaryRow(row)))
        return false;
    return anyData ? everSeen : Model::isCoreRow(row);
}

// The details table: the HI83 details, and beside them ship motion and inclination.
bool rowInDetails(models::LatestValuesModel::Row row, bool everSeen)
{
    using Model = models::LatestValuesModel;
    return everSeen && (Model::isDetailRow(row) || Model::isSecondaryRow(row));
}

// The values and details tables: read-only rows, every column in full (no horizontal scroll bar).
// A value that stopped arriving (LatestValuesModel::StaleRole) is drawn in the disabled
// text colour: its number is still there to read, with its age, but no longer live.
class StaleValueDelegate : public QStyledItemDelegate {
public:
    using QStyledItemDelegate::QStyledItemDelegate;

protected:
    void initStyleOption(QStyleOptionViewItem *option, const QModelIndex &index) const override
    {
        QStyledItemDelegate::initStyleOption(option, index);
        if (index.data(models::LatestValuesModel::StaleRole).toBool()) {
            const QColor grey = option->palette.color(QPalette::Disabled, QPalette::Text);
            option->palette.setColor(QPalette::Text, grey);
            option->palette.setColor(QPalette::HighlightedText, grey);
            option->font.setItalic(true);
        }
    }
};

void setUpValuesTable(QTableView *view)
{
    view->setItemDelegate(new StaleValueDelegate(view));
    view->verticalHeader()->hide();
    // The line height and a pixel of spacing: an INS module's rows (35 with ship motion and
    // inclination, in Chinese) still fit a laptop screen.
    view->verticalHeader()->setMinimumSectionSize(view->fontMetrics().height() + 1);
    view->verticalHeader()->setDefaultSectionSize(view->fontMetrics().height() + 1);
    view->setAlternatingRowColors(true);
    view->setSelectionBehavior(QAbstractItemView::SelectRows);
    view->setEditTriggers(QAbstractItemView::NoEditTriggers);
    view->setWordWrap(false);
    view->setCornerButtonEnabled(false);
    view->horizontalHeader()->setDefaultAlignment(Qt::AlignLeft | Qt::AlignVCenter);
    view->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
}

QDockWidget *makeDock(QWidget *content, const QString &objectName)
{
    auto *dock = new QDockWidget(content->parentWidget());
    dock->setObjectName(objectName);
    dock->setWidget(content);
    return dock;
}

bool busyState(SessionState s)
{
    return s == SessionState::Opening || s == SessionState::Detecting || s == SessionState::Connected
        || s == SessionState::Reconnecting;
}

QString rateText(double hz)
{
    return QString::number(hz, 'f', hz >= 10 ? 0 : 1);
}

constexpr int kLayoutVersion = 4; // 4: attitude in a dock of its own, bottom panels closed

} // namespace

DeviceWorkspace::DeviceWorkspace(QWidget *parent) : QMainWindow(parent)
{
    setObjectName(QStringLiteral("deviceWorkspace"));
    setWindowFlags(Qt::Widget); // lives inside a tab
    setDockOptions(AllowNestedDocks | AllowTabbedDocks);

    // The live values.
    m_valuesModel = new models::LatestValuesModel(this);
    m_valuesView = new QTableView(this);
    m_valuesView->setObjectName(QStringLiteral("valuesView"));
    m_valuesView->setModel(m_valuesModel);
    setUpValuesTable(m_valuesView);
    auto *header = m_valuesView->horizontalHeader();
    // Every column in full (resizeValueColumns() sizes them and the view's minimum width):
    // a narrow dock never hides the numbers or units behind a scroll bar.
    header->setSectionResizeMode(QHeaderView::Fixed);
    header->setStretchLastSection(true);
    for (int r = 0; r < models::LatestValuesModel::RowCount; ++r)
        m_valuesView->setRowHidden(r, !rowInTable(models::LatestValuesModel::Row(r), false, false));
    // The details (an INS configuration's HI83 extras, and beside them ship motion and
    // inclination), from the same model: their columns sized to their texts (vectors of
    // three), shown once a frame carried an HI83 extra.
    m_detailsView = new QTableView(this);
    m_detailsView->setObjectName(QStringLiteral("detailsView"));
    m_detailsView->setModel(m_valuesModel);
    setUpValuesTable(m_detailsView);
    m_detailsView->horizontalHeader()->setSectionResizeMode(QHeaderView::Fixed);
    m_detailsView->horizontalHeader()->setStretchLastSection(true);
    for (int r = 0; r < models::LatestValuesModel::RowCount; ++r)
        m_detailsView->setRowHidden(r, true);
    // Centre: the live charts.
    m_charts = new ChartPanel(this);
    m_charts->setObjectName(QStringLiteral("chartPanel"));
    setCentralWidget(m_charts);

    // Right: the values, and below them the 3D attitude, each a dock of its own; a link's
    // settings behind the values. Below the charts, as tabs: the text console,
    // the raw link traffic, the log of every command this window sent with its reply, and
    // the recording controls. applyPreset() puts them in place.
    m_valuesDock = makeDock(m_valuesView, QStringLiteral("valuesDock"));
    m_detailsDock = makeDock(m_detailsView, QStringLiteral("detailsDock"));
    m_attitude = new AttitudeWidget(this);
    m_attitude->setObjectName(QStringLiteral("attitudeWidget"));
    m_attitudeDock = makeDock(m_attitude, QStringLiteral("attitudeDock"));
    connect(m_attitude, &AttitudeWidget::ghostRequested, this, &DeviceWorkspace::showReference);
    // The right column runs the whole height: the panels below the charts never shorten the
    // attitude view.
    setCorner(Qt::TopRightCorner, Qt::RightDockWidgetArea);
    setCorner(Qt::BottomRightCorner, Qt::RightDockWidgetArea);

    m_console = new ConsoleWidget(this);
    m_console->setObjectName(QStringLiteral("console"));
    m_consoleDock = makeDock(m_console, QStringLiteral("consoleDock"));
    m_rawView = new RawBytesView(this);
    m_rawView->setObjectName(QStringLiteral("rawBytesView"));
    m_rawDock = makeDock(m_rawView, QStringLiteral("rawBytesDock"));
    m_commandLog = new CommandLogWidget(this);
    m_commandLog->setObjectName(QStringLiteral("commandLog"));
    m_commandLogDock = makeDock(m_commandLog, QStringLiteral("commandLogDock"));
    m_configDock = new QDockWidget(this); // its panel comes with a link that has settings
    m_configDock->setObjectName(QStringLiteral("configDock"));
    m_recording = new RecordingControls(this);
    m_recording->setObjectName(QStringLiteral("recordingControls"));
    m_recordingDock = makeDock(m_recording, QStringLiteral("recordingDock"));
    // The link's clocks: each stream's state, drift and jitter (refreshed with the statistics,
    // twice a second).
    m_clockModel = new models::ClockStatsModel(this);
    m_syncView = new QTableView(this);
    m_syncView->setObjectName(QStringLiteral("syncView"));
    m_syncView->setModel(m_clockModel);
    m_syncView->verticalHeader()->hide();
    m_syncView->setSelectionMode(QAbstractItemView::NoSelection);
    m_syncView->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    m_syncView->horizontalHeader()->setSectionResizeMode(models::ClockStatsModel::StateColumn, QHeaderView::Stretch);
    m_syncDock = makeDock(m_syncView, QStringLiteral("syncDock"));
    connect(m_recording, &RecordingControls::recordingFailed, this, &DeviceWorkspace::onErrorOccurred);
    bindLink(std::make_unique<device::NoLink>(), {}); // nothing connected yet
    // The Monitor layout: the settings hidden until asked for (Device > Configuration, or the
    // Configure layout), the panels below the charts closed until needed (View menu, Ctrl+`
    // for the console, an ERR reply, a recording).
    applyPreset(LayoutPreset::Monitor);
    m_consoleDock->toggleViewAction()->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_QuoteLeft));
    connect(m_recording, &RecordingControls::recordingStarted, this, [this] { openDock(m_recordingDock); });

    createStatusBar();

    connect(m_console, &ConsoleWidget::commandSubmitted, this, &DeviceWorkspace::sendConsoleCommand);

    m_refreshTimer.setInterval(kRefreshIntervalMs);
    m_refreshTimer.setTimerType(Qt::PreciseTimer);
    connect(&m_refreshTimer, &QTimer::timeout, this, &DeviceWorkspace::refreshViews);

    retranslateUi();
    onStateChanged(SessionState::Closed, QString());
}

DeviceWorkspace::~DeviceWorkspace()
{
    dropLink(); // before the simulator behind it goes
}

void DeviceWorkspace::dropLink()
{
    // What refers to the link goes first: its docks, the settings panel, the recorder and the
    // raw-bytes view; then the link (and its port), then what it needed.
    for (QDockWidget *dock : std::exchange(m_linkDocks, {})) {
        removeDockWidget(dock);
        delete dock;
    }
    m_linkDockPlaces.clear();
    m_linkTools.clear();
    m_charts->offerOutputSwitch(0, {}, {}); // it calls the link that goes now
    m_start = {}; // it opens the link that goes now
    delete std::exchange(m_configPanel, nullptr);
    m_recording->setSession(nullptr);
    m_rawView->setLog(nullptr);
    if (m_link) {
        m_link->disconnect(this);
        m_link->close();
        m_link.reset();
    }
    m_linkKeepAlive.reset();
}

void DeviceWorkspace::offerTool(LinkTool tool, ToolRunner run)
{
    m_linkTools.insert(int(tool), std::move(run));
}

bool DeviceWorkspace::runTool(LinkTool tool, QWidget *dialogParent)
{
    const auto it = m_linkTools.constFind(int(tool));
    if (it == m_linkTools.constEnd())
        return false;
    (*it)(dialogParent);
    return true;
}

void DeviceWorkspace::setConfigPanel(ConfigPanel *panel)
{
    delete std::exchange(m_configPanel, panel);
    if (!panel)
        return;
    panel->setParent(m_configDock);
    panel->setObjectName(QStringLiteral("configPanel"));
    m_configDock->setWidget(panel);
}

void DeviceWorkspace::noteBaud(int baud)
{
    m_baud = baud;
    updateStatsLabel();
}

bool DeviceWorkspace::attachLink(std::unique_ptr<device::DeviceLink> link, const QString &target,
                                 std::shared_ptr<void> keepAlive, std::function<void()> start, const QString &address)
{
    if (isBusy() || !link)
        return false;
    m_portLent = false;
    bindLink(std::move(link), std::move(keepAlive));
    m_target = target;
    m_address = address;
    m_start = std::move(start);
    m_baud = 0;
    Q_EMIT titleChanged(title());
    return true;
}

void DeviceWorkspace::startLink()
{
    if (!m_start || isBusy())
        return;
    const SessionState before = m_state;
    m_start();
    // A link reports Opening from its own thread a moment later: the tab is taken from now on
    // (a second link opened at once, as a session's replays are, goes to another tab).
    if (m_state == before)
        onStateChanged(SessionState::Opening, m_target);
}

void DeviceWorkspace::bindLink(std::unique_ptr<device::DeviceLink> link, std::shared_ptr<void> keepAlive)
{
    dropLink();
    m_link = std::move(link);
    m_linkKeepAlive = std::move(keepAlive);
    resetViews();

    device::DeviceLink *l = m_link.get();
    connect(l, &device::DeviceLink::stateChanged, this, &DeviceWorkspace::onStateChanged);
    connect(l, &device::DeviceLink::identityChanged, this, &DeviceWorkspace::onIdentityChanged);
    connect(l, &device::DeviceLink::statsUpdated, this, &DeviceWorkspace::onStatsUpdated);
    connect(l, &device::DeviceLink::errorOccurred, this, &DeviceWorkspace::onErrorOccurred);
    connect(l, &device::DeviceLink::streamWarning, this, &DeviceWorkspace::onStreamWarning);
    connect(l, &device::DeviceLink::textReplied, this, &DeviceWorkspace::onTextReplied);
    connect(l, &device::DeviceLink::textReceived, m_console, &ConsoleWidget::showText);
    m_console->setCompletions(l->textCommands());
    if (auto *session = qobject_cast<device::Session *>(l)) {
        m_rawView->setLog(&session->rawLog());
        if (l->capabilities().testFlag(device::DeviceLink::Capability::Recording))
            m_recording->setSession(session); // a byte stream worth a capture
    }
    const auto caps = capabilities();
    m_console->setInputEnabled(caps.testFlag(device::DeviceLink::Capability::TextCommands));
    m_recording->setEnabled(caps.testFlag(device::DeviceLink::Capability::Recording));
    for (const auto &[dock, capability] : capabilityDocks())
        if (!caps.testFlag(capability))
            dock->hide(); // not for this link
}

void DeviceWorkspace::applyPreferences(const Preferences &prefs)
{
    m_refreshTimer.setInterval(prefs.refreshIntervalMs());
    m_charts->setUnits(prefs.units);
    m_charts->setHistoryMinutes(prefs.historyMinutes);
    m_valuesModel->setUnits(prefs.units);
    m_attitude->setDisplayFrame(prefs.frame == Preferences::Frame::Ned ? AttitudeWidget::DisplayFrame::Ned
                                                                       : AttitudeWidget::DisplayFrame::Enu);
    m_recording->setFolder(prefs.effectiveRecordingFolder());
    m_recording->setPattern(prefs.recordingPattern);
    if (auto *session = qobject_cast<device::Session *>(m_link.get()); session && isBusy() && !isSimulated())
        session->setAutoReconnect(prefs.autoReconnect);
}

void DeviceWorkspace::resetViews()
{
    m_detailsOffered = false;
    m_detailsColumns = {};
    m_detailsView->setMinimumWidth(0);
    m_detailsDock->hide();
    m_identity.reset();
    m_stats.reset();
    m_clockModel->setClocks({});
    m_chartSeq = 0;
    m_shownTotal = ~quint64(0);
    m_charts->clear();
}

bool DeviceWorkspace::isBusy() const
{
    return busyState(m_state);
}

QString DeviceWorkspace::title() const
{
    if (m_target.isEmpty())
        return tr("New connection");
    // A target that names the product already ("HEC495 on /dev/ttyUSB0") is not named twice.
    const QString product = m_identity ? QString::fromStdString(m_identity->productName) : QString();
    if (!product.isEmpty() && !m_target.startsWith(product))
        return tr("%1 on %2").arg(product, m_target);
    return m_target;
}

QList<QAction *> DeviceWorkspace::dockActions() const
{
    QList<QAction *> actions;
    for (QDockWidget *dock : findChildren<QDockWidget *>(QString(), Qt::FindDirectChildrenOnly))
        if (offersDock(dock))
            actions << dock->toggleViewAction();
    return actions;
}

QByteArray DeviceWorkspace::saveLayout() const
{
    return saveState(kLayoutVersion);
}

bool DeviceWorkspace::restoreLayout(const QByteArray &state)
{
    m_layoutRestored = !state.isEmpty() && restoreState(state, kLayoutVersion);
    return m_layoutRestored;
}

void DeviceWorkspace::disconnectDevice()
{
    m_portLent = false;
    if (isBusy())
        link().close(); // the simulator stops when the link reports Closed
    else
        m_linkKeepAlive.reset();
}

QString DeviceWorkspace::releasePort()
{
    m_portLent = true;
    if (isBusy())
        m_link->close();
    return m_address;
}

void DeviceWorkspace::reclaimPort(const std::function<void()> &open)
{
    m_portLent = false;
    if (isBusy())
        return;
    m_identity.reset();
    m_stats.reset();
    m_clockModel->setClocks({});
    if (!open || !m_start) {
        startLink();
        return;
    }
    const SessionState before = m_state;
    open();
    if (m_state == before)
        onStateChanged(SessionState::Opening, m_target);
}

void DeviceWorkspace::sendConsoleCommand(const QString &text)
{
    if (const quint64 id = m_link->sendText(text, kCommandTimeoutMs))
        showSentCommand(id, text); // 0: the console takes no input for this link
}

void DeviceWorkspace::showSentCommand(quint64 id, const QString &text)
{
    m_console->showCommand(id, text);
    m_commandLog->record(id, text);
}


void DeviceWorkspace::pullSamples()
{
    const auto batch = link().store().since(m_chartSeq, kMaxSamplesPerTick, &m_chartSeq);
    if (!batch.empty())
        m_charts->appendSamples(batch);
    if (m_reference)
        for (const model::Sample &s : batch)
            m_reference->add(s);
}

void DeviceWorkspace::showReference(bool shown)
{
    if (shown) {
        m_reference = std::make_unique<verify::LiveReference>();
        m_referenceClock.start();
    } else
        m_reference.reset();
    m_attitude->setGhostShown(shown);
}

void DeviceWorkspace::refreshViews()
{
    if (window()->isMinimized())
        return;
    Q_EMIT viewTick();
    // Charts: the samples that arrived since the last tick, then one redraw of what is on screen.
    pullSamples();
    device::SampleStore &store = link().store();
    m_charts->refresh();
    if (!m_rawDock->visibleRegion().isEmpty())
        m_rawView->refresh();
    const quint64 total = store.totalAppended();
    // Nothing new: the values only need their ages once a second (a value that stopped
    // arriving is shown greyed with its age).
    if (total == m_shownTotal && m_valuesClock.isValid() && m_valuesClock.elapsed() < kStaleCheckIntervalMs)
        return;
    const std::optional<model::Sample> latest = store.latest();
    // The 3D attitude on every tick, so that it moves smoothly.
    if (latest && latest->has(model::FieldQuat))
        m_attitude->setQuaternion(latest->quat);
    else if (latest && latest->has(model::FieldEuler)) // links that send angles only
        m_attitude->setQuaternion(model::quatFromEnu312(model::Euler{latest->roll, latest->pitch, latest->yaw}));
    // ImuDesk's reference beside it (the attitude view's context menu), in the module's frame.
    if (m_reference && latest && (latest->has(model::FieldQuat) || latest->has(model::FieldEuler))) {
        const model::Quat reported = latest->has(model::FieldQuat)
            ? latest->quat
            : model::quatFromEnu312(model::Euler{latest->roll, latest->pitch, latest->yaw});
        if (m_reference->started()) {
            const Eigen::Quaterniond r = m_reference->attitude();
            const double apart =
                m_reference->differenceDeg(Eigen::Quaterniond(reported.w, reported.x, reported.y, reported.z));
            m_attitude->setGhost(model::Quat{r.w(), r.x(), r.y(), r.z()},
                                 tr("Reference %1° apart (±%2°)").arg(apart, 0, 'f', 1).arg(m_reference->sigmaDeg(), 0, 'f', 1));
            m_attitude->addGhostDifference(double(m_referenceClock.nsecsElapsed()) * 1e-9, apart);
        } else {
            m_attitude->setGhost(reported, tr("Reference: hold the module still for 1 s to start it"));
        }
    }
    // The numbers at most ten times a second: digits that change faster cannot be read, and
    // their text layout is a good part of the GUI thread's work at 1 kHz. A tick that skips
    // them leaves m_shownTotal behind, so the newest values always arrive.
    if (m_valuesClock.isValid() && m_valuesClock.elapsed() < kValuesIntervalMs)
        return;
    m_valuesClock.restart();
    m_shownTotal = total;
    // Each quantity's latest value, whichever frame brought it (angles-only frames between full
    // records, NMEA between binary frames).
    std::optional<model::Sample> values = store.latestPerField();
    // Before firmware 1.7.0 the MAIN_STATUS bytes are reserved: show them as not reported.
    if (values && m_identity && m_identity->firmware && !m_identity->hasMainStatus())
        values->fields &= ~uint32_t(model::FieldMainStatus);
    // A replay's samples carry the recording's host times: no ages there.
    m_valuesModel->refresh(values, link().isLive() ? store.fieldAges() : device::SampleStore::FieldAges{});
    // The rows follow what the link sends (see rowInTable).
    bool rowsChanged = false;
    const bool anyData = m_valuesModel->everSeen(models::LatestValuesModel::FrameType);
    using Model = models::LatestValuesModel;
    bool anyDetail = false;
    for (int r = Model::UtcDate; r <= Model::GnssVelocity; ++r)
        anyDetail = anyDetail || m_valuesModel->everSeen(Model::Row(r));
    if (anyDetail && !m_detailsOffered) { // a tab beside the values, which stay in front
        m_detailsOffered = true;
        placeDetailsDock();
        rowsChanged = true; // the right column makes room for the details' columns
    }
    for (int r = 0; r < Model::RowCount; ++r) {
        const auto row = Model::Row(r);
        const bool seen = m_valuesModel->everSeen(row);
        const bool hide = !rowInTable(row, seen, anyData, m_detailsOffered);
        if (m_valuesView->isRowHidden(r) != hide) {
            m_valuesView->setRowHidden(r, hide);
            rowsChanged = true;
        }
        const bool hideDetail = !(m_detailsOffered && rowInDetails(row, seen));
        if (m_detailsView->isRowHidden(r) != hideDetail)
            m_detailsView->setRowHidden(r, hideDetail);
    }
    if (m_detailsOffered)
        resizeDetailColumns();
    if (rowsChanged && followsWindow())
        fitDocks(); // room for the new rows
    m_flags->setStatus(values && values->has(model::FieldMainStatus) ? std::optional<quint16>(values->mainStatus)
                                                                     : std::nullopt);
}

void DeviceWorkspace::onStateChanged(SessionState state, const QString &detail)
{
    m_state = state;
    m_stateDetail = detail;
    if (!busyState(state) && !m_portLent)
        m_linkKeepAlive.reset(); // the port is closed already: what the link needed (its simulator) goes
    m_console->setInputEnabled(state == SessionState::Connected);
    updateStateLabel();
    updateStatsLabel();
    Q_EMIT stateChanged(state);
    Q_EMIT titleChanged(title());
}

void DeviceWorkspace::onIdentityChanged(const model::DeviceIdentity &identity)
{
    m_identity = identity;
    m_shownTotal = ~quint64(0); // the identity decides whether MAIN_STATUS is shown
    // A module set to NWU (CONFIG IMU COORD 4): drawn and labelled in that frame.
    m_attitude->setWorldFrame(identity.worldFrame, identity.worldFrameAssumed);
    m_valuesModel->setWorldFrame(identity.worldFrame);
    updateIdentityLabel();
    Q_EMIT titleChanged(title());
}

void DeviceWorkspace::onStatsUpdated(const device::SessionStats &stats)
{
    m_stats = stats;
    m_clockModel->setClocks(stats.clocks);
    if (stats.baud > 0)
        m_baud = stats.baud; // the rate found by a detection, or followed after a change
    updateStatsLabel();
}

void DeviceWorkspace::onTextReplied(quint64 id, const device::TextReply &reply)
{
    m_console->showReply(id, reply);
    m_commandLog->complete(id, reply);
    if (!reply.ok())
        openDock(m_consoleDock); // the user sees the ERR and what the device said
}

void DeviceWorkspace::onErrorOccurred(const QString &message)
{
    m_console->showError(message);
    Q_EMIT errorReported(message);
}

// Not a modal: the condition may end by itself (the device back at its rate), and the note goes
// when it does; the console keeps both ends.
void DeviceWorkspace::onStreamWarning(const QString &message)
{
    const bool wasShown = !m_streamWarningLabel->isHidden();
    m_streamWarningLabel->setText(message);
    m_streamWarningLabel->setToolTip(message);
    m_streamWarningLabel->setVisible(!message.isEmpty());
    if (!message.isEmpty())
        m_console->showError(message);
    else if (wasShown)
        m_console->showText(tr("Frames arrive again on %1.").arg(m_target));
}

QString DeviceWorkspace::statusText() const
{
    QStringList parts;
    for (const QLabel *label : {m_stateLabel, m_identityLabel})
        if (!label->text().isEmpty())
            parts << label->text();
    if (!m_statsPlainText.isEmpty())
        parts << m_statsPlainText; // the label's own text carries the highlight's markup
    return parts.join(QStringLiteral(" | "));
}

void DeviceWorkspace::updateStateLabel()
{
    QString text;
    switch (m_state) {
    case SessionState::Closed: text = tr("Not connected"); break;
    case SessionState::Opening: text = tr("Opening %1…").arg(m_target); break;
    case SessionState::Detecting: text = tr("Detecting the baud rate of %1…").arg(m_target); break;
    case SessionState::Connected: text = tr("Connected"); break;
    case SessionState::Disconnected: text = tr("Connection to %1 lost").arg(m_target); break;
    case SessionState::Reconnecting:
        text = tr("Disconnected from %1 — waiting for the device to come back").arg(m_target);
        break;
    case SessionState::Failed: text = tr("Could not connect to %1").arg(m_target); break;
    }
    m_stateLabel->setText(text);
    m_stateLabel->setToolTip(m_target.isEmpty() ? m_stateDetail : m_target + QLatin1Char('\n') + m_stateDetail);
}

void DeviceWorkspace::updateIdentityLabel()
{
    QStringList parts;
    if (m_identity) {
        if (!m_identity->productName.empty())
            parts << QString::fromStdString(m_identity->productName);
        if (m_identity->firmware)
            parts << tr("firmware %1").arg(QString::fromStdString(m_identity->firmware->toString()));
        if (!m_identity->serial.empty())
            parts << tr("SN %1").arg(QString::fromStdString(m_identity->serial));
        if (m_identity->worldFrameAssumed) // LOG COMCONFIG named no COORD
            parts << tr("world frame %1 assumed").arg(QLatin1String(model::worldFrameName(m_identity->worldFrame)));
    }
    m_identityLabel->setText(parts.join(QStringLiteral(" · ")));
    m_identityLabel->setVisible(!parts.isEmpty());
    if (m_identity) {
        QStringList tip;
        tip << tr("Product: %1").arg(QString::fromStdString(m_identity->productName));
        if (!m_identity->build.empty())
            tip << tr("Build: %1").arg(QString::fromStdString(m_identity->build));
        if (m_identity->bootloader)
            tip << tr("Bootloader: %1").arg(QString::fromStdString(m_identity->bootloader->toString()));
        if (m_identity->worldFrameAssumed)
            tip << tr("The module's LOG COMCONFIG reply names no COORD: its attitude is drawn as %1, the default, "
                      "which it did not confirm (CONFIG IMU COORD sets it)")
                       .arg(QLatin1String(model::worldFrameName(m_identity->worldFrame)));
        m_identityLabel->setToolTip(tip.join(QLatin1Char('\n')));
    }
}

void DeviceWorkspace::updateStatsLabel()
{
    if (!m_stats || !isBusy()) {
        m_statsPlainText = isBusy() && m_baud > 0 ? tr("%1 baud").arg(m_baud) : QString();
        m_statsLabel->setText(m_statsPlainText.toHtmlEscaped());
        m_statsLabel->setVisible(!m_statsLabel->text().isEmpty());
        return;
    }
    const device::SessionStats &s = *m_stats;
    QStringList parts;
    const int baud = s.baud > 0 ? s.baud : m_baud;
    if (baud > 0)
        parts << tr("%1 baud").arg(baud);
    QStringList rates;
    for (const auto &[name, hz] : s.rateByType)
        if (hz > 0)
            rates << tr("%1 %2 Hz").arg(QString::fromStdString(name), rateText(hz));
    parts << (rates.isEmpty() ? tr("no frames") : rates.join(QStringLiteral(", ")));
    parts << tr("load %1%").arg(qRound(s.linkLoad * 100));
    // Counts of damage stand out once they are not zero (amber, as a warning flag): a frame
    // lost is what a bench engineer must not miss among the rates.
    QStringList shown;
    for (const QString &p : std::as_const(parts))
        shown << p.toHtmlEscaped();
    const auto counted = [&](const QString &text, uint64_t count) {
        parts << text;
        shown << (count == 0 ? text.toHtmlEscaped()
                             : QStringLiteral("<span style=\"background:#ef6c00; color:black; font-weight:bold\">"
                                              "&nbsp;%1&nbsp;</span>")
                                   .arg(text.toHtmlEscaped()));
    };
    counted(tr("CRC errors %1").arg(s.crcErrors), s.crcErrors);
    counted(tr("lost %1").arg(s.framesLost), s.framesLost);
    parts << tr("skipped %1 B").arg(s.bytesSkipped);
    shown << parts.last().toHtmlEscaped();
    m_statsPlainText = parts.join(QStringLiteral(" · "));
    m_statsLabel->setText(shown.join(QStringLiteral(" · ")));
    m_statsLabel->setVisible(true);
    m_statsLabel->setToolTip(tr("Received %1 bytes, %2 frames, %3 NMEA sentences.\n"
                                "Errors: %4 CRC, %5 length, %6 payload, %7 NMEA; %8 bytes skipped.\n"
                                "Frames lost (gaps in the device time): %9.\n"
                                "Link load = bytes per second × 10 bits / baud rate.")
                                 .arg(s.bytesIn)
                                 .arg(s.frames)
                                 .arg(s.nmeaSentences)
                                 .arg(s.crcErrors)
                                 .arg(s.lengthErrors)
                                 .arg(s.payloadErrors)
                                 .arg(s.nmeaErrors)
                                 .arg(s.bytesSkipped)
                                 .arg(s.framesLost));
}

void DeviceWorkspace::createStatusBar()
{
    m_stateLabel = new QLabel(this);
    m_stateLabel->setObjectName(QStringLiteral("stateLabel"));
    m_identityLabel = new QLabel(this);
    m_identityLabel->setObjectName(QStringLiteral("identityLabel"));
    m_statsLabel = new QLabel(this);
    m_statsLabel->setObjectName(QStringLiteral("statsLabel"));
    m_statsLabel->setTextFormat(Qt::RichText);
    m_streamWarningLabel = new QLabel(this);
    m_streamWarningLabel->setObjectName(QStringLiteral("streamWarningLabel"));
    m_streamWarningLabel->setWordWrap(true);
    m_streamWarningLabel->setStyleSheet(QStringLiteral("QLabel { color: #a04000; font-weight: bold; }"));
    m_streamWarningLabel->hide();
    m_flags = new StatusFlagsWidget(this);
    m_flags->setObjectName(QStringLiteral("statusFlags"));
    m_flags->setSizePolicy(QSizePolicy::Fixed, QSizePolicy::Preferred);
    // Narrow windows clip the texts, never the flags.
    for (QLabel *label : {m_identityLabel, m_statsLabel})
        label->setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Preferred);

    // Two lines on the left (state and identity; link counters), the flags on the right.
    auto *info = new QWidget(this);
    auto *firstLine = new QHBoxLayout;
    firstLine->setSpacing(16);
    firstLine->addWidget(m_stateLabel);
    firstLine->addWidget(m_identityLabel, 1);
    auto *lines = new QVBoxLayout(info);
    lines->setContentsMargins(2, 0, 2, 0);
    lines->setSpacing(0);
    lines->addLayout(firstLine);
    lines->addWidget(m_streamWarningLabel);
    lines->addWidget(m_statsLabel);
    statusBar()->addWidget(info, 1);
    statusBar()->addPermanentWidget(m_flags);
    statusBar()->setSizeGripEnabled(false);
}

void DeviceWorkspace::retranslateUi()
{
    m_consoleDock->setWindowTitle(tr("Console"));
    m_rawDock->setWindowTitle(tr("Raw bytes"));
    m_commandLogDock->setWindowTitle(tr("Command log"));
    m_valuesDock->setWindowTitle(tr("Values"));
    m_detailsDock->setWindowTitle(tr("Details"));
    m_attitudeDock->setWindowTitle(tr("3D attitude"));
    m_configDock->setWindowTitle(tr("Configuration"));
    m_recordingDock->setWindowTitle(tr("Recording"));
    m_syncDock->setWindowTitle(tr("Time sync"));
    m_valuesModel->retranslate();
    resizeValueColumns();
    updateStateLabel();
    updateIdentityLabel();
    updateStatsLabel();
}

void DeviceWorkspace::changeEvent(QEvent *event)
{
    if (event->type() == QEvent::LanguageChange)
        retranslateUi();
    QMainWindow::changeEvent(event);
}

// The view clock runs only while this workspace is on screen (current tab, window not minimised).
void DeviceWorkspace::showEvent(QShowEvent *event)
{
    QMainWindow::showEvent(event);
    if (!m_shownOnce) {
        m_shownOnce = true;
        // Once the layout has a size: the preset's proportions, or a check of the restored ones.
        if (m_layoutRestored)
            repairLayout();
        else
            fitDocks();
    }
    m_refreshTimer.start();
    refreshViews();
}

void DeviceWorkspace::hideEvent(QHideEvent *event)
{
    m_refreshTimer.stop();
    QMainWindow::hideEvent(event);
}

} // namespace imudesk::ui
