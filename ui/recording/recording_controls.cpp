#include "recording/recording_controls.h"

#include "device/session.h"
#include "record/recording.h"

#include <QDateTime>
#include <QDir>
#include <QFileInfo>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QLocale>
#include <QPushButton>
#include <QRegularExpression>
#include <QSettings>
#include <QSpinBox>

namespace imudesk::ui {

RecordingControls::RecordingControls(QWidget *parent) : QWidget(parent)
{
    m_record = new QPushButton(tr("Record"), this);
    m_record->setObjectName(QStringLiteral("record"));
    m_stop = new QPushButton(tr("Stop"), this);
    m_stop->setObjectName(QStringLiteral("stop"));
    m_folder = new QLineEdit(QDir::homePath(), this);
    m_folder->setObjectName(QStringLiteral("folder"));
    m_folder->setToolTip(tr("Folder the capture files are written to"));
    m_pattern = new QLineEdit(QString::fromLatin1(kDefaultPattern), this);
    m_pattern->setObjectName(QStringLiteral("pattern"));
    m_pattern->setToolTip(tr("File name; {date}, {time}, {product} and {serial} are filled in. Ending in .imucap: every "
                             "byte, to replay and export later; ending in .mcap: the decoded samples as MCAP, which "
                             "PlotJuggler, Foxglove and Lichtblick open"));
    m_duration = new QSpinBox(this);
    m_duration->setObjectName(QStringLiteral("duration"));
    m_duration->setRange(0, 7 * 24 * 3600);
    m_duration->setSuffix(tr(" s"));
    m_duration->setSpecialValueText(tr("until Stop"));
    m_duration->setToolTip(tr("Stop the recording by itself after this many seconds (0: until you press Stop)"));
    m_duration->setValue(QSettings().value(QStringLiteral("recording/durationS"), 0).toInt());
    connect(m_duration, &QSpinBox::valueChanged, this,
            [](int s) { QSettings().setValue(QStringLiteral("recording/durationS"), s); });
    m_stopTimer.setSingleShot(true);
    connect(&m_stopTimer, &QTimer::timeout, this, [this] {
        if (m_recording || m_pending)
            m_stoppedByDuration = true;
        stopRecording();
    });
    m_elapsed = new QLabel(this);
    m_elapsed->setObjectName(QStringLiteral("elapsed"));
    m_size = new QLabel(this);
    m_size->setObjectName(QStringLiteral("size"));
    m_frames = new QLabel(this);
    m_frames->setObjectName(QStringLiteral("frames"));
    m_message = new QLabel(this);
    m_message->setObjectName(QStringLiteral("message"));
    m_message->setWordWrap(true);

    auto *row = new QHBoxLayout;
    row->addWidget(m_record);
    row->addWidget(m_stop);
    row->addWidget(new QLabel(tr("Folder:"), this));
    row->addWidget(m_folder, 2);
    row->addWidget(new QLabel(tr("File:"), this));
    row->addWidget(m_pattern, 2);
    row->addWidget(new QLabel(tr("Stop after:"), this));
    row->addWidget(m_duration);
    row->addWidget(m_elapsed);
    row->addWidget(m_size);
    row->addWidget(m_frames);
    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addLayout(row);
    layout->addWidget(m_message);

    connect(m_record, &QPushButton::clicked, this, &RecordingControls::startRecording);
    connect(m_stop, &QPushButton::clicked, this, &RecordingControls::stopRecording);
    m_clock.setInterval(500);
    connect(&m_clock, &QTimer::timeout, this, &RecordingControls::refresh);
    refresh();
    updateButtons();
}

void RecordingControls::setSession(device::Session *session)
{
    if (m_session)
        disconnect(m_session, nullptr, this, nullptr);
    m_session = session;
    m_recording = m_pending = false;
    if (m_session) {
        connect(m_session, &device::Session::recordingStarted, this, &RecordingControls::onStarted);
        connect(m_session, &device::Session::recordingStopped, this, &RecordingControls::onStopped);
        connect(m_session, &device::Session::recordingProgress, this, &RecordingControls::onProgress);
        connect(m_session, &device::Session::identityChanged, this,
                [this](const model::DeviceIdentity &id) {
                    setIdentity(QString::fromStdString(id.productName), QString::fromStdString(id.serial));
                });
        connect(m_session, &QObject::destroyed, this, [this] { setSession(nullptr); });
    }
    updateButtons();
}

void RecordingControls::setIdentity(const QString &product, const QString &serial)
{
    m_product = product;
    m_serial = serial;
}

void RecordingControls::setFolder(const QString &folder)
{
    if (m_showingRecording)
        m_userFolder = folder;
    else
        m_folder->setText(folder);
}

QString RecordingControls::folder() const
{
    return m_showingRecording ? m_userFolder : m_folder->text();
}

void RecordingControls::setPattern(const QString &pattern)
{
    if (m_showingRecording)
        m_userPattern = pattern;
    else
        m_pattern->setText(pattern);
}

QString RecordingControls::pattern() const
{
    return m_showingRecording ? m_userPattern : m_pattern->text();
}

QString RecordingControls::expandPattern(const QString &pattern) const
{
    return expandPattern(pattern, m_product, m_serial, QDateTime::currentDateTime());
}

QString RecordingControls::expandPattern(const QString &pattern, const QString &product, const QString &serial,
                                         const QDateTime &when)
{
    QString name = pattern;
    name.replace(QLatin1String("{date}"), when.toString(QStringLiteral("yyyyMMdd")));
    name.replace(QLatin1String("{time}"), when.toString(QStringLiteral("HHmmss")));
    name.replace(QLatin1String("{product}"), product.isEmpty() ? QStringLiteral("device") : product);
    name.replace(QLatin1String("{serial}"), serial.isEmpty() ? QStringLiteral("unknown") : serial);
    // Nothing that leaves the folder or upsets a file system.
    static const QRegularExpression unsafe(QStringLiteral("[/\\\\:*?\"<>|\\x00-\\x1f\\x7f]"));
    name.replace(unsafe, QStringLiteral("_"));
    // A device's serial or product string is not trusted: no hidden file, no name a file system refuses.
    while (name.startsWith(QLatin1Char('.')))
        name.replace(0, 1, QLatin1Char('_'));
    name.truncate(200);
    // A name ending in .mcap records MCAP (the decoded samples, for the field's tools); any other
    // a capture.
    if (!name.endsWith(QLatin1String(".imucap")) && !name.endsWith(QLatin1String(".mcap"), Qt::CaseInsensitive))
        name += QLatin1String(".imucap");
    return name;
}

void RecordingControls::setDurationS(int seconds)
{
    m_duration->setValue(seconds);
}

int RecordingControls::durationS() const
{
    return m_duration->value();
}

void RecordingControls::startRecording()
{
    if (!m_session || m_recording || m_pending)
        return;
    if (m_session->state() != device::SessionState::Connected) {
        m_message->setText(tr("Not recording: the device is not connected. Press Connect (Ctrl+K), then Record "
                              "(Ctrl+R)."));
        return;
    }
    if (m_showingRecording) { // a recording that ended with a drop-out: the user's fields again
        m_showingRecording = false;
        m_interrupted = false;
        m_folder->setText(m_userFolder);
        m_pattern->setText(m_userPattern);
    }
    const QDir dir(m_folder->text());
    if (!dir.exists()) {
        m_message->setText(tr("The folder %1 does not exist. Choose another one.").arg(m_folder->text()));
        return;
    }
    m_path = dir.filePath(expandPattern(m_pattern->text()));
    m_pending = true;
    m_message->clear();
    record::startRecording(*m_session, m_path);
    updateButtons();
}

void RecordingControls::stopRecording()
{
    if (m_session && (m_recording || m_pending))
        m_session->stopRecording();
}

void RecordingControls::onStarted(const QString &path)
{
    // The same file again after a drop-out (a device that comes back goes on recording into
    // it): the recording goes on, and so does its clock.
    const bool goesOn = !m_recording && path == m_path && m_since.isValid() && m_interrupted;
    m_pending = false;
    m_recording = true;
    m_interrupted = false;
    m_path = path;
    if (!goesOn) {
        m_bytes = m_frameCount = 0;
        m_since.start();
        m_stoppedByDuration = false;
        m_stopTimer.stop();
        if (m_duration->value() > 0)
            m_stopTimer.start(m_duration->value() * 1000);
    }
    m_clock.start();
    // While recording, the fields show where this recording goes (a session's folder and this
    // device's file when Record all devices started it), not the template; the user's own
    // folder and pattern come back when it stops.
    if (!m_showingRecording) {
        m_userFolder = m_folder->text();
        m_userPattern = m_pattern->text();
        m_showingRecording = true;
    }
    const QFileInfo info(path);
    m_folder->setText(QDir::toNativeSeparators(info.absolutePath()));
    m_pattern->setText(info.fileName());
    m_folder->setCursorPosition(0);
    m_pattern->setCursorPosition(0);
    m_message->setText(tr("Recording to %1").arg(path));
    refresh();
    updateButtons();
    Q_EMIT recordingStarted(path);
}

void RecordingControls::onStopped(const QString &reason)
{
    const bool was = m_recording;
    m_pending = false;
    m_recording = false;
    m_interrupted = was && !reason.isEmpty();
    m_clock.stop();
    if (!m_interrupted)
        m_stopTimer.stop(); // (a drop-out's recording goes on when the device comes back, and so does its end)
    if (m_showingRecording && !m_interrupted) {
        m_showingRecording = false;
        m_folder->setText(m_userFolder);
        m_pattern->setText(m_userPattern);
    }
    refresh();
    updateButtons();
    if (!reason.isEmpty()) {
        m_message->setText(reason);
        Q_EMIT recordingFailed(reason);
    } else if (was && m_stoppedByDuration) {
        m_message->setText(tr("Saved %1 (stopped after %2 s, as set)").arg(m_path).arg(m_duration->value()));
    } else if (was) {
        m_message->setText(tr("Saved %1").arg(m_path));
    }
    if (was)
        Q_EMIT recordingStopped(m_path);
}

void RecordingControls::onProgress(quint64 bytes, quint64 frames)
{
    m_bytes = bytes;
    m_frameCount = frames;
    refresh();
}

void RecordingControls::refresh()
{
    const qint64 s = (m_recording || m_interrupted) && m_since.isValid() ? m_since.elapsed() / 1000 : 0;
    m_elapsed->setText(tr("%1:%2:%3")
                           .arg(s / 3600, 2, 10, QLatin1Char('0'))
                           .arg(s / 60 % 60, 2, 10, QLatin1Char('0'))
                           .arg(s % 60, 2, 10, QLatin1Char('0')));
    // Our own units (Qt's "bytes" is not translated by every distribution's qtbase catalogue).
    const double b = double(m_bytes);
    if (b < 1024.0)
        m_size->setText(tr("%1 B").arg(m_bytes));
    else if (b < 1024.0 * 1024.0)
        m_size->setText(tr("%1 KiB").arg(b / 1024.0, 0, 'f', 1));
    else if (b < 1024.0 * 1024.0 * 1024.0)
        m_size->setText(tr("%1 MiB").arg(b / (1024.0 * 1024.0), 0, 'f', 1));
    else
        m_size->setText(tr("%1 GiB").arg(b / (1024.0 * 1024.0 * 1024.0), 0, 'f', 2));
    m_frames->setText(tr("%n frame(s)", nullptr, int(std::min<quint64>(m_frameCount, INT32_MAX))));
}

void RecordingControls::updateButtons()
{
    const bool busy = m_recording || m_pending;
    m_record->setEnabled(m_session && !busy);
    m_stop->setEnabled(m_session && busy);
    m_folder->setEnabled(!busy);
    m_pattern->setEnabled(!busy);
    m_duration->setEnabled(!busy);
}

} // namespace imudesk::ui
