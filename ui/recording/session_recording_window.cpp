#include "session_recording_window.h"

#include "record/session_exporter.h"
#include "recording/twist_align_dialog.h"

#include <QCloseEvent>
#include <QDateTime>
#include <QDir>
#include <QEvent>
#include <QFileDialog>
#include <QFileInfo>
#include <QGridLayout>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QMessageBox>
#include <QPushButton>
#include <QTableWidget>
#include <QVBoxLayout>

namespace imudesk::ui {

namespace {
// The devices table's columns (names of their own: this file is compiled in one unit with others).
enum SessionColumn { SessionNameColumn, SessionLinkColumn, SessionBytesColumn, SessionFramesColumn, SessionStateColumn,
                     SessionColumnCount };
}

SessionRecordingWindow::SessionRecordingWindow(DeviceSource source, const QString &parentFolder, QWidget *parent)
    : QWidget(parent, Qt::Window), m_source(std::move(source))
{
    setObjectName(QStringLiteral("sessionRecordingWindow"));
    m_intro = new QLabel(this);
    m_intro->setWordWrap(true);
    m_folderLabel = new QLabel(this);
    m_folderEdit = new QLineEdit(parentFolder, this);
    m_folderEdit->setObjectName(QStringLiteral("sessionParentFolder"));
    m_chooseButton = new QPushButton(this);
    connect(m_chooseButton, &QPushButton::clicked, this, [this] {
        const QString dir = QFileDialog::getExistingDirectory(this, tr("Folder for the session"), m_folderEdit->text());
        if (!dir.isEmpty())
            m_folderEdit->setText(dir);
    });
    m_startButton = new QPushButton(this);
    m_startButton->setObjectName(QStringLiteral("startSessionRecording"));
    connect(m_startButton, &QPushButton::clicked, this, &SessionRecordingWindow::start);
    m_stopButton = new QPushButton(this);
    m_stopButton->setObjectName(QStringLiteral("stopSessionRecording"));
    connect(m_stopButton, &QPushButton::clicked, this, &SessionRecordingWindow::stop);
    m_exportButton = new QPushButton(this);
    m_exportButton->setObjectName(QStringLiteral("exportSession"));
    connect(m_exportButton, &QPushButton::clicked, this, &SessionRecordingWindow::exportAligned);
    m_alignButton = new QPushButton(this);
    m_alignButton->setObjectName(QStringLiteral("twistAlignSession"));
    connect(m_alignButton, &QPushButton::clicked, this, &SessionRecordingWindow::openTwistAlign);
    m_table = new QTableWidget(0, SessionColumnCount, this);
    m_table->setObjectName(QStringLiteral("sessionDevices"));
    m_table->verticalHeader()->hide();
    m_table->setEditTriggers(QAbstractItemView::NoEditTriggers);
    m_table->setSelectionMode(QAbstractItemView::NoSelection);
    m_table->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    m_table->horizontalHeader()->setSectionResizeMode(SessionStateColumn, QHeaderView::Stretch);
    m_status = new QLabel(this);
    m_status->setObjectName(QStringLiteral("sessionStatus"));
    m_status->setWordWrap(true);
    m_status->setTextInteractionFlags(Qt::TextSelectableByMouse);

    auto *folderRow = new QHBoxLayout;
    folderRow->addWidget(m_folderLabel);
    folderRow->addWidget(m_folderEdit, 1);
    folderRow->addWidget(m_chooseButton);
    auto *buttons = new QHBoxLayout;
    buttons->addWidget(m_startButton);
    buttons->addWidget(m_stopButton);
    buttons->addStretch(1);
    buttons->addWidget(m_exportButton);
    buttons->addWidget(m_alignButton);
    auto *layout = new QVBoxLayout(this);
    layout->addWidget(m_intro);
    layout->addLayout(folderRow);
    layout->addLayout(buttons);
    layout->addWidget(m_table, 1);
    layout->addWidget(m_status);
    resize(760, 380);

    m_refresh.setInterval(500); // the recordings report twice a second
    connect(&m_refresh, &QTimer::timeout, this, &SessionRecordingWindow::refreshTable);
    connect(&m_exportJob, &jobs::BackgroundJob::finished, this, [this](bool ok, const QString &message) {
        const QString text = ok ? tr("Exported the aligned session to %1.").arg(m_exportOutput) : message;
        m_status->setText(text);
        updateButtons();
        Q_EMIT exportFinished(ok, text);
    });
    retranslateUi();
    updateButtons();
}

SessionRecordingWindow::~SessionRecordingWindow() = default;

void SessionRecordingWindow::setParentFolder(const QString &folder)
{
    m_folderEdit->setText(folder);
}

QString SessionRecordingWindow::parentFolder() const
{
    return m_folderEdit->text();
}

void SessionRecordingWindow::retranslateUi()
{
    setWindowTitle(tr("Record all devices"));
    m_intro->setText(tr("Records every connected device into one session folder: each device's capture and "
                        "session.json with their clocks. Replays and exports put the devices on one time base."));
    m_folderLabel->setText(tr("Into:"));
    m_folderEdit->setToolTip(tr("A new folder session-<date>-<time> is made here for each session"));
    m_chooseButton->setText(tr("Choose…"));
    m_startButton->setText(tr("&Start"));
    m_startButton->setToolTip(tr("Start recording every connected device"));
    m_stopButton->setText(tr("S&top"));
    m_exportButton->setText(tr("&Export aligned…"));
    m_exportButton->setToolTip(tr("The last session as one tidy CSV, every device's samples in the order of the common time"));
    m_alignButton->setText(tr("T&wist to align…"));
    m_alignButton->setToolTip(tr("Find each device's constant offset from sharp turns of a shared fixture"));
    m_table->setHorizontalHeaderLabels({tr("Device"), tr("Link"), tr("Bytes"), tr("Frames"), tr("State")});
}

void SessionRecordingWindow::changeEvent(QEvent *event)
{
    if (event->type() == QEvent::LanguageChange)
        retranslateUi();
    QWidget::changeEvent(event);
}

void SessionRecordingWindow::closeEvent(QCloseEvent *event)
{
    if (isRecording()) {
        // Closing the window must not lose the session: the recordings stop, the manifest is
        // written, then the window closes (onFinished).
        m_closeWhenDone = true;
        stop();
        event->ignore();
        return;
    }
    m_exportJob.cancel(); // a running export stops at its next rows, its partial file removed
    QWidget::closeEvent(event);
}

void SessionRecordingWindow::updateButtons()
{
    const bool recording = isRecording();
    const bool exporting = m_exportJob.isRunning();
    m_startButton->setEnabled(!recording && !exporting);
    m_stopButton->setEnabled(recording);
    m_folderEdit->setEnabled(!recording);
    m_chooseButton->setEnabled(!recording);
    m_exportButton->setEnabled(!recording && !exporting && !m_lastSession.isEmpty());
    m_alignButton->setEnabled(!recording && !m_lastSession.isEmpty());
}

void SessionRecordingWindow::start()
{
    if (isRecording())
        return;
    m_devices = m_source ? m_source() : std::vector<Device>{};
    std::vector<device::GroupRecording::Member> members;
    for (const Device &d : m_devices)
        if (d.session)
            members.push_back({d.session.data(), QString(), d.address, d.identity}); // named by capture::deviceName
    if (members.empty()) {
        m_status->setText(tr("No connected device can be recorded: connect the devices in their tabs first."));
        return;
    }
    const QString folder = QDir(m_folderEdit->text())
                               .filePath(QStringLiteral("session-%1")
                                             .arg(QDateTime::currentDateTime().toString(QStringLiteral("yyyyMMdd-HHmmss"))));
    m_group = std::make_unique<device::GroupRecording>();
    connect(m_group.get(), &device::GroupRecording::finished, this, &SessionRecordingWindow::onFinished);
    connect(m_group.get(), &device::GroupRecording::deviceEvent, this, [this](int, const QString &) { refreshTable(); });
    QString error;
    if (!m_group->start(folder, members, &error)) {
        m_status->setText(error);
        m_group.reset();
        return;
    }
    m_elapsed.start();
    m_refresh.start();
    m_status->setText(tr("Recording %n device(s) into %1…", nullptr, int(members.size())).arg(folder));
    refreshTable();
    updateButtons();
}

void SessionRecordingWindow::stop()
{
    if (m_group)
        m_group->stop();
}

void SessionRecordingWindow::refreshTable()
{
    if (!m_group)
        return;
    const auto &devices = m_group->manifest().devices;
    m_table->setRowCount(int(devices.size()));
    auto set = [this](int row, int col, const QString &text) {
        auto *item = m_table->item(row, col);
        if (!item) {
            item = new QTableWidgetItem;
            if (col == SessionBytesColumn || col == SessionFramesColumn)
                item->setTextAlignment(Qt::AlignRight | Qt::AlignVCenter);
            m_table->setItem(row, col, item);
        }
        if (item->text() != text)
            item->setText(text);
    };
    for (int i = 0; i < int(devices.size()); ++i) {
        const auto &d = devices[size_t(i)];
        set(i, SessionNameColumn, d.name);
        set(i, SessionLinkColumn, d.linkKind);
        set(i, SessionBytesColumn, QLocale().toString(qulonglong(d.bytes)));
        set(i, SessionFramesColumn, QLocale().toString(qulonglong(d.frames)));
        QString state = tr("recording");
        if (!d.events.empty()) {
            const auto &last = d.events.back();
            state = last.what == QLatin1String("disconnected") ? tr("dropped out: %1").arg(last.detail)
                : last.what == QLatin1String("reconnected")    ? tr("back after a drop-out, recording")
                                                               : tr("stopped: %1").arg(last.detail);
        }
        if (!m_group->running())
            state = d.droppedOut() ? tr("dropped out (marked in the session)") : tr("complete");
        set(i, SessionStateColumn, state);
    }
    if (m_group->running())
        m_status->setText(tr("Recording for %1 s into %2")
                              .arg(m_elapsed.elapsed() / 1000)
                              .arg(QDir::toNativeSeparators(m_group->folder())));
}

void SessionRecordingWindow::onFinished(const QString &manifestPath, const QString &error)
{
    m_refresh.stop();
    refreshTable();
    const bool ok = error.isEmpty();
    if (ok) {
        m_lastSession = QFileInfo(manifestPath).absolutePath();
        m_status->setText(tr("Session recorded in %1.").arg(QDir::toNativeSeparators(m_lastSession)));
    } else {
        m_status->setText(tr("The recordings stopped, but the session's manifest could not be written: %1. The "
                             "captures are in %2.")
                              .arg(error, QDir::toNativeSeparators(m_group->folder())));
    }
    updateButtons();
    Q_EMIT recordingFinished(ok ? m_lastSession : m_group->folder(), ok);
    if (std::exchange(m_closeWhenDone, false))
        close();
}

void SessionRecordingWindow::exportAligned()
{
    if (m_lastSession.isEmpty() || m_exportJob.isRunning())
        return;
    record::SessionExporter::Options o;
    o.output = m_lastSession + QStringLiteral(".csv");
    m_exportOutput = o.output;
    const QString folder = m_lastSession;
    m_status->setText(tr("Exporting the session…"));
    m_exportJob.launch(QStringLiteral("imudesk-export-session"), [folder, o](const jobs::BackgroundJob::Context &job) {
        record::SessionExporter::Options options = o;
        options.cancelled = job.cancelled;
        const auto r = record::SessionExporter::run(folder, options);
        return jobs::BackgroundJob::Outcome{r.ok, r.error, {}};
    });
    updateButtons();
}

void SessionRecordingWindow::openTwistAlign()
{
    auto *dialog = new TwistAlignDialog(m_lastSession, this);
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    dialog->show();
}

} // namespace imudesk::ui
