#include "main_window.h"

#include "connection_bar.h"
#include "console_widget.h"
#include "models/latest_values_model.h"
#include "sim/pty_simulator.h"
#include "status_flags_widget.h"

#include <QAction>
#include <QApplication>
#include <QDockWidget>
#include <QEvent>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QKeySequence>
#include <QLabel>
#include <QMenu>
#include <QMenuBar>
#include <QMessageBox>
#include <QStatusBar>
#include <QTableView>
#include <QToolBar>
#include <QVBoxLayout>
#include <QWindowStateChangeEvent>

namespace imudesk::ui {

using device::SessionState;

namespace {

bool isBusy(SessionState s)
{
    return s == SessionState::Opening || s == SessionState::Detecting || s == SessionState::Connected;
}

QString rateText(double hz)
{
    return QString::number(hz, 'f', hz >= 10 ? 0 : 1);
}

} // namespace

MainWindow::MainWindow(const WindowSettings &settings, QWidget *parent) : QMainWindow(parent)
{
    setObjectName(QStringLiteral("mainWindow"));

    // Centre: the live values.
    m_valuesModel = new models::LatestValuesModel(this);
    m_valuesView = new QTableView(this);
    m_valuesView->setObjectName(QStringLiteral("valuesView"));
    m_valuesView->setModel(m_valuesModel);
    m_valuesView->verticalHeader()->hide();
    m_valuesView->verticalHeader()->setDefaultSectionSize(m_valuesView->fontMetrics().height() + 6);
    m_valuesView->setAlternatingRowColors(true);
    m_valuesView->setSelectionBehavior(QAbstractItemView::SelectRows);
    m_valuesView->setEditTriggers(QAbstractItemView::NoEditTriggers);
    m_valuesView->setWordWrap(false);
    m_valuesView->setCornerButtonEnabled(false);
    // Fixed widths (no per-tick resizing): quantity and value side by side, the unit column takes the rest.
    auto *header = m_valuesView->horizontalHeader();
    header->setSectionResizeMode(QHeaderView::Interactive);
    header->setStretchLastSection(true);
    header->setDefaultAlignment(Qt::AlignLeft | Qt::AlignVCenter);
    setCentralWidget(m_valuesView);

    // Top: the connection bar.
    m_connectionBar = new ConnectionBar(this);
    m_connectionBar->setObjectName(QStringLiteral("connectionBar"));
    auto *toolBar = new QToolBar(this);
    toolBar->setObjectName(QStringLiteral("connectionToolBar"));
    toolBar->setMovable(false);
    toolBar->setFloatable(false);
    toolBar->toggleViewAction()->setVisible(false);
    toolBar->addWidget(m_connectionBar);
    addToolBar(Qt::TopToolBarArea, toolBar);

    // Bottom dock: the ASCII console.
    m_console = new ConsoleWidget(this);
    m_console->setObjectName(QStringLiteral("console"));
    m_consoleDock = new QDockWidget(this);
    m_consoleDock->setObjectName(QStringLiteral("consoleDock"));
    m_consoleDock->setWidget(m_console);
    addDockWidget(Qt::BottomDockWidgetArea, m_consoleDock);

    createActions();
    createMenus();
    createStatusBar();

    connect(m_connectionBar, &ConnectionBar::connectRequested, this, &MainWindow::connectSelected);
    connect(m_connectionBar, &ConnectionBar::disconnectRequested, this, &MainWindow::disconnectDevice);
    connect(m_console, &ConsoleWidget::commandSubmitted, this, &MainWindow::sendConsoleCommand);

    connect(&m_session, &device::DeviceSession::stateChanged, this, &MainWindow::onStateChanged);
    connect(&m_session, &device::DeviceSession::identityChanged, this, &MainWindow::onIdentityChanged);
    connect(&m_session, &device::DeviceSession::statsUpdated, this, &MainWindow::onStatsUpdated);
    connect(&m_session, &device::DeviceSession::baudDetected, this, &MainWindow::onBaudDetected);
    connect(&m_session, &device::DeviceSession::commandFinished, this, &MainWindow::onCommandFinished);
    connect(&m_session, &device::DeviceSession::textReceived, m_console, &ConsoleWidget::showText);
    connect(&m_session, &device::DeviceSession::errorOccurred, this, &MainWindow::onErrorOccurred);

    m_refreshTimer.setInterval(kRefreshIntervalMs);
    m_refreshTimer.setTimerType(Qt::PreciseTimer);
    connect(&m_refreshTimer, &QTimer::timeout, this, &MainWindow::refreshViews);

    retranslateUi();
    restoreSettings(settings);
    onStateChanged(SessionState::Closed, QString());
}

MainWindow::~MainWindow()
{
    // Close the port before the simulator behind it goes away.
    m_session.disconnect(this);
    m_session.close();
}

WindowSettings MainWindow::windowSettings() const
{
    WindowSettings s;
    s.geometry = saveGeometry();
    s.windowState = saveState(WindowSettings::kVersion);
    s.port = m_connectionBar->selectedPort().key();
    s.baud = m_connectionBar->selectedBaud();
    return s;
}

void MainWindow::restoreSettings(const WindowSettings &settings)
{
    if (settings.geometry.isEmpty() || !restoreGeometry(settings.geometry))
        resize(1100, 840);
    if (settings.windowState.isEmpty() || !restoreState(settings.windowState, WindowSettings::kVersion))
        resizeDocks({m_consoleDock}, {220}, Qt::Vertical);
    const PortChoice port = PortChoice::fromKey(settings.port);
    if (port.isValid())
        m_connectionBar->selectPort(port);
    m_connectionBar->selectBaud(settings.baud);
}

void MainWindow::connectPort(const QString &port, int baud)
{
    if (isBusy(m_state))
        return;
    stopSimulator();
    m_identity.reset();
    m_stats.reset();
    m_baud = baud;
    m_target = port;
    m_connectionBar->selectPort(PortChoice::serial(port));
    m_connectionBar->selectBaud(baud);
    m_session.open(port, baud);
}

bool MainWindow::connectSimulated(const sim::SimOptions &options, int baud, QString *error)
{
    if (isBusy(m_state)) {
        if (error)
            *error = tr("Disconnect first, then connect to the simulated device.");
        return false;
    }
    stopSimulator();
    auto simulator = std::make_unique<sim::PtySimulator>(options);
    QString why;
    if (!simulator->start(&why)) {
        if (error)
            *error = tr("The simulated device could not start: %1").arg(why);
        return false;
    }
    m_simulator = std::move(simulator);
    m_identity.reset();
    m_stats.reset();
    m_baud = baud;
    const QString model = QString::fromStdString(options.model);
    const QString firmware = QString::fromStdString(options.firmware);
    m_target = tr("Simulated %1 (firmware %2)").arg(model, firmware);
    m_connectionBar->selectPort(PortChoice::simulated(model, firmware));
    m_connectionBar->selectBaud(baud);
    m_session.open(m_simulator->devicePath(), baud);
    return true;
}

void MainWindow::disconnectDevice()
{
    if (isBusy(m_state))
        m_session.close(); // the simulator stops when the session reports Closed
    else
        stopSimulator();
}

void MainWindow::connectSelected()
{
    if (isBusy(m_state))
        return;
    const PortChoice choice = m_connectionBar->selectedPort();
    const int baud = m_connectionBar->selectedBaud();
    switch (choice.kind) {
    case PortChoice::Kind::Serial: connectPort(choice.port, baud); break;
    case PortChoice::Kind::Simulated: {
        sim::SimOptions options;
        options.model = choice.model.toStdString();
        options.firmware = choice.firmware.toStdString();
        options.motion = m_simMotion;
        QString error;
        if (!connectSimulated(options, baud, &error))
            presentError(error);
        break;
    }
    case PortChoice::Kind::None: presentError(tr("Choose a port first.")); break;
    }
}

void MainWindow::sendConsoleCommand(const QString &text)
{
    const quint64 id = m_session.sendCommand(text, kCommandTimeoutMs);
    m_console->showCommand(id, text);
}

void MainWindow::stopSimulator()
{
    if (!m_simulator)
        return;
    m_simulator->stop();
    m_simulator.reset();
}

void MainWindow::refreshViews()
{
    if (isMinimized())
        return;
    const quint64 total = m_session.store().totalAppended();
    if (total == m_shownTotal)
        return;
    m_shownTotal = total;
    std::optional<model::Sample> latest = m_session.store().latest();
    // Before firmware 1.7.0 the MAIN_STATUS bytes are reserved: show them as not reported.
    if (latest && m_identity && m_identity->firmware && !m_identity->hasMainStatus())
        latest->fields &= ~uint32_t(model::FieldMainStatus);
    m_valuesModel->refresh(latest);
    m_flags->setStatus(latest && latest->has(model::FieldMainStatus) ? std::optional<quint16>(latest->mainStatus)
                                                                     : std::nullopt);
}

void MainWindow::presentError(const QString &message)
{
    if (m_errorPresenter) {
        m_errorPresenter(message);
        return;
    }
    // Never block: a non-modal box, reused while it is open.
    if (m_errorBox) {
        constexpr qsizetype kMaxText = 4000;
        if (m_errorBox->text().size() < kMaxText)
            m_errorBox->setText(m_errorBox->text() + QStringLiteral("\n\n") + message);
        return;
    }
    auto *box = new QMessageBox(QMessageBox::Warning, tr("ImuDesk"), message, QMessageBox::Ok, this);
    box->setAttribute(Qt::WA_DeleteOnClose);
    box->setWindowModality(Qt::NonModal);
    box->show();
    m_errorBox = box;
}

void MainWindow::showAbout()
{
    QMessageBox::about(this, tr("About ImuDesk"),
                       tr("<h3>ImuDesk %1</h3><p>A bench tool for HiPNUC IMU modules: live values, the ASCII "
                          "command console and simulated devices.</p><p>Built with Qt %2.</p>")
                           .arg(QCoreApplication::applicationVersion(), QString::fromLatin1(qVersion())));
}

void MainWindow::onStateChanged(SessionState state, const QString &detail)
{
    m_state = state;
    m_stateDetail = detail;
    if (!isBusy(state))
        stopSimulator(); // the port is closed already
    m_connectionBar->setSessionState(state);
    m_console->setInputEnabled(state == SessionState::Connected);
    updateStateLabel();
    updateStatsLabel();
    updateActions();
    updateTitle();
}

void MainWindow::onIdentityChanged(const model::DeviceIdentity &identity)
{
    m_identity = identity;
    m_shownTotal = ~quint64(0); // the identity decides whether MAIN_STATUS is shown
    updateIdentityLabel();
    updateTitle();
}

void MainWindow::onStatsUpdated(const device::SessionStats &stats)
{
    m_stats = stats;
    updateStatsLabel();
}

void MainWindow::onBaudDetected(int baud)
{
    m_baud = baud;
    updateStatsLabel();
}

void MainWindow::onCommandFinished(quint64 id, const protocol::hipnuc::AsciiReply &reply)
{
    m_console->showReply(id, reply);
    // A LOG VERSION sent from the console or the Device menu refreshes the identity too.
    const QString command = QString::fromStdString(reply.command).simplified();
    if (reply.ok() && command.compare(QLatin1String("LOG VERSION"), Qt::CaseInsensitive) == 0) {
        const auto identity = model::DeviceIdentity::fromKeyValues(reply.values);
        if (identity.usable())
            onIdentityChanged(identity);
    }
}

void MainWindow::onErrorOccurred(const QString &message)
{
    m_console->showError(message);
    presentError(message);
}

QString MainWindow::statusText() const
{
    QStringList parts;
    for (const QLabel *label : {m_stateLabel, m_identityLabel, m_statsLabel})
        if (!label->text().isEmpty())
            parts << label->text();
    return parts.join(QStringLiteral(" | "));
}

void MainWindow::updateStateLabel()
{
    QString text;
    switch (m_state) {
    case SessionState::Closed: text = tr("Not connected"); break;
    case SessionState::Opening: text = tr("Opening %1…").arg(m_target); break;
    case SessionState::Detecting: text = tr("Detecting the baud rate of %1…").arg(m_target); break;
    case SessionState::Connected: text = tr("Connected"); break;
    case SessionState::Disconnected: text = tr("Connection to %1 lost").arg(m_target); break;
    case SessionState::Failed: text = tr("Could not connect to %1").arg(m_target); break;
    }
    m_stateLabel->setText(text);
    m_stateLabel->setToolTip(m_target.isEmpty() ? m_stateDetail : m_target + QLatin1Char('\n') + m_stateDetail);
}

void MainWindow::updateIdentityLabel()
{
    QStringList parts;
    if (m_identity) {
        if (!m_identity->productName.empty())
            parts << QString::fromStdString(m_identity->productName);
        if (m_identity->firmware)
            parts << tr("firmware %1").arg(QString::fromStdString(m_identity->firmware->toString()));
        if (!m_identity->serial.empty())
            parts << tr("SN %1").arg(QString::fromStdString(m_identity->serial));
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
        m_identityLabel->setToolTip(tip.join(QLatin1Char('\n')));
    }
}

void MainWindow::updateStatsLabel()
{
    if (!m_stats || !isBusy(m_state)) {
        m_statsLabel->setText(isBusy(m_state) && m_baud > 0 ? tr("%1 baud").arg(m_baud) : QString());
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
    parts << tr("CRC errors %1").arg(s.crcErrors);
    parts << tr("skipped %1 B").arg(s.bytesSkipped);
    m_statsLabel->setText(parts.join(QStringLiteral(" · ")));
    m_statsLabel->setVisible(true);
    m_statsLabel->setToolTip(tr("Received %1 bytes, %2 frames, %3 NMEA sentences.\n"
                                "Errors: %4 CRC, %5 length, %6 payload, %7 NMEA; %8 bytes skipped.\n"
                                "Link load = bytes per second × 10 bits / baud rate.")
                                 .arg(s.bytesIn)
                                 .arg(s.frames)
                                 .arg(s.nmeaSentences)
                                 .arg(s.crcErrors)
                                 .arg(s.lengthErrors)
                                 .arg(s.payloadErrors)
                                 .arg(s.nmeaErrors)
                                 .arg(s.bytesSkipped));
}

void MainWindow::updateTitle()
{
    const QString base = tr("ImuDesk – IMU bench tool");
    if (m_identity && isBusy(m_state) && !m_identity->productName.empty())
        setWindowTitle(tr("%1 – %2").arg(QString::fromStdString(m_identity->productName), base));
    else
        setWindowTitle(base);
}

void MainWindow::updateActions()
{
    const bool busy = isBusy(m_state);
    m_connectAction->setEnabled(!busy);
    m_disconnectAction->setEnabled(busy);
    m_versionAction->setEnabled(m_state == SessionState::Connected);
}

void MainWindow::createActions()
{
    m_quitAction = new QAction(this);
    m_quitAction->setObjectName(QStringLiteral("quitAction"));
    m_quitAction->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_Q));
    m_quitAction->setMenuRole(QAction::QuitRole);
    connect(m_quitAction, &QAction::triggered, this, &QWidget::close);

    m_connectAction = new QAction(this);
    m_connectAction->setObjectName(QStringLiteral("connectAction"));
    m_connectAction->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_K));
    connect(m_connectAction, &QAction::triggered, this, &MainWindow::connectSelected);

    m_disconnectAction = new QAction(this);
    m_disconnectAction->setObjectName(QStringLiteral("disconnectAction"));
    m_disconnectAction->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_D));
    connect(m_disconnectAction, &QAction::triggered, this, &MainWindow::disconnectDevice);

    m_versionAction = new QAction(this);
    m_versionAction->setObjectName(QStringLiteral("versionAction"));
    connect(m_versionAction, &QAction::triggered, this,
            [this] { m_console->submit(QStringLiteral("LOG VERSION")); });

    m_aboutAction = new QAction(this);
    m_aboutAction->setObjectName(QStringLiteral("aboutAction"));
    m_aboutAction->setMenuRole(QAction::AboutRole);
    connect(m_aboutAction, &QAction::triggered, this, &MainWindow::showAbout);
}

void MainWindow::createMenus()
{
    m_fileMenu = menuBar()->addMenu(QString());
    m_fileMenu->addAction(m_quitAction);
    m_deviceMenu = menuBar()->addMenu(QString());
    m_deviceMenu->addAction(m_connectAction);
    m_deviceMenu->addAction(m_disconnectAction);
    m_deviceMenu->addSeparator();
    m_deviceMenu->addAction(m_versionAction);
    m_viewMenu = menuBar()->addMenu(QString());
    m_viewMenu->addAction(m_consoleDock->toggleViewAction());
    m_helpMenu = menuBar()->addMenu(QString());
    m_helpMenu->addAction(m_aboutAction);
}

void MainWindow::createStatusBar()
{
    m_stateLabel = new QLabel(this);
    m_stateLabel->setObjectName(QStringLiteral("stateLabel"));
    m_identityLabel = new QLabel(this);
    m_identityLabel->setObjectName(QStringLiteral("identityLabel"));
    m_statsLabel = new QLabel(this);
    m_statsLabel->setObjectName(QStringLiteral("statsLabel"));
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
    lines->addWidget(m_statsLabel);
    statusBar()->addWidget(info, 1);
    statusBar()->addPermanentWidget(m_flags);
}

void MainWindow::retranslateUi()
{
    m_fileMenu->setTitle(tr("&File"));
    m_deviceMenu->setTitle(tr("&Device"));
    m_viewMenu->setTitle(tr("&View"));
    m_helpMenu->setTitle(tr("&Help"));
    m_quitAction->setText(tr("&Quit"));
    m_connectAction->setText(tr("&Connect"));
    m_connectAction->setStatusTip(tr("Connect to the port chosen in the connection bar"));
    m_disconnectAction->setText(tr("&Disconnect"));
    m_versionAction->setText(tr("Send LOG &VERSION"));
    m_versionAction->setStatusTip(tr("Ask the device for its product name, firmware and serial number"));
    m_aboutAction->setText(tr("&About ImuDesk"));
    m_consoleDock->setWindowTitle(tr("Console"));
    if (auto *bar = findChild<QToolBar *>(QStringLiteral("connectionToolBar")))
        bar->setWindowTitle(tr("Connection"));
    m_valuesModel->retranslate();
    resizeValueColumns();
    updateStateLabel();
    updateIdentityLabel();
    updateStatsLabel();
    updateTitle();
}

void MainWindow::resizeValueColumns()
{
    using Model = models::LatestValuesModel;
    m_valuesView->resizeColumnToContents(Model::QuantityColumn);
    // Room for a long MAIN_STATUS text; numbers are right-aligned next to the quantity.
    const int valueWidth =
        m_valuesView->fontMetrics().horizontalAdvance(QStringLiteral("WB_CONV MAG_DIST ATT_CONV STATIC MAG_AIDING UTC_UNSYNC (0x0000)")) + 16;
    m_valuesView->setColumnWidth(Model::ValueColumn, valueWidth);
}

void MainWindow::changeEvent(QEvent *event)
{
    switch (event->type()) {
    case QEvent::LanguageChange: retranslateUi(); break;
    case QEvent::WindowStateChange:
        if (isMinimized())
            m_refreshTimer.stop();
        else if (isVisible())
            m_refreshTimer.start();
        break;
    default: break;
    }
    QMainWindow::changeEvent(event);
}

void MainWindow::showEvent(QShowEvent *event)
{
    QMainWindow::showEvent(event);
    if (!isMinimized())
        m_refreshTimer.start();
    refreshViews();
}

void MainWindow::hideEvent(QHideEvent *event)
{
    m_refreshTimer.stop();
    QMainWindow::hideEvent(event);
}

} // namespace imudesk::ui
