#include "recording/export_dialog.h"

#include "record/session_exporter.h"
#include "record/session_manifest.h"

#include <QComboBox>
#include <QDesktopServices>
#include <QDir>
#include <QStandardItemModel>
#include <QUrl>
#include <QDialogButtonBox>
#include <QDoubleSpinBox>
#include <QFileDialog>
#include <QFileInfo>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QProgressBar>
#include <QPushButton>
#include <QThread>
#include <QVBoxLayout>

namespace imudesk::ui {

using Format = record::CaptureExporter::Format;

ExportDialog::ExportDialog(const QString &capturePath, QWidget *parent) : QDialog(parent)
{
    m_captureEdit = new QLineEdit(this);
    m_captureEdit->setObjectName(QStringLiteral("capture"));
    m_captureEdit->setToolTip(tr("The capture to export: a recording, a vendor CSV or a raw byte dump; or a recorded "
                                 "session's folder (or its session.json): every device, aligned in one file"));
    m_chooseCapture = new QPushButton(tr("Choose…"), this);
    m_chooseCapture->setObjectName(QStringLiteral("chooseCapture"));
    m_chooseCapture->setToolTip(tr("Export another capture"));
    m_format = new QComboBox(this);
    m_format->setObjectName(QStringLiteral("format"));
    m_format->addItem(tr("Vendor CSV (the vendor tool's layout; a file per frame type when there are several)"), int(Format::VendorCsv));
    m_format->addItem(tr("Tidy CSV (pandas, PlotJuggler)"), int(Format::TidyCsv));
    m_format->addItem(tr("JSON Lines"), int(Format::JsonLines));
    m_format->addItem(tr("MCAP (ROS 2: PlotJuggler, Foxglove, Lichtblick)"), int(Format::Mcap));
    m_format->addItem(tr("MATLAB .mat (a struct per device, SI units)"), int(Format::Mat));
    m_output = new QLineEdit(this);
    m_output->setObjectName(QStringLiteral("output"));
    m_from = new QDoubleSpinBox(this);
    m_from->setObjectName(QStringLiteral("from"));
    m_from->setRange(0, 1e7);
    m_from->setDecimals(3);
    m_from->setSuffix(tr(" s"));
    m_to = new QDoubleSpinBox(this);
    m_to->setObjectName(QStringLiteral("to"));
    m_to->setRange(-1, 1e7);
    m_to->setDecimals(3);
    m_to->setSuffix(tr(" s"));
    m_to->setSpecialValueText(tr("end"));
    m_to->setValue(-1);
    m_progress = new QProgressBar(this);
    m_progress->setObjectName(QStringLiteral("progress"));
    m_progress->setRange(0, 1000);
    m_progress->setValue(0);
    m_status = new QLabel(this);
    m_status->setObjectName(QStringLiteral("status"));
    m_status->setWordWrap(true);
    auto *buttons = new QDialogButtonBox(this);
    m_export = buttons->addButton(tr("Export"), QDialogButtonBox::AcceptRole);
    m_export->setObjectName(QStringLiteral("export"));
    m_cancel = buttons->addButton(QDialogButtonBox::Cancel);
    m_cancel->setObjectName(QStringLiteral("cancel"));
    m_showFolder = buttons->addButton(tr("Show in folder"), QDialogButtonBox::ActionRole);
    m_showFolder->setObjectName(QStringLiteral("showFolder"));
    m_showFolder->setToolTip(tr("Open the folder of the written file in the file manager"));
    m_showFolder->hide();

    auto *captureRow = new QHBoxLayout;
    captureRow->addWidget(m_captureEdit, 1);
    captureRow->addWidget(m_chooseCapture);
    auto *form = new QFormLayout;
    form->addRow(tr("Capture:"), captureRow);
    form->addRow(tr("Format:"), m_format);
    form->addRow(tr("Output:"), m_output);
    form->addRow(tr("From:"), m_from);
    form->addRow(tr("To:"), m_to);
    auto *layout = new QVBoxLayout(this);
    layout->addLayout(form);
    layout->addWidget(m_progress);
    layout->addWidget(m_status);
    layout->addWidget(buttons);

    connect(m_captureEdit, &QLineEdit::editingFinished, this, [this] {
        if (m_captureEdit->text() != m_capture)
            setCapture(m_captureEdit->text());
    });
    connect(m_chooseCapture, &QPushButton::clicked, this, &ExportDialog::chooseCapture);
    connect(m_format, &QComboBox::currentIndexChanged, this, &ExportDialog::suggestOutput);
    connect(m_export, &QPushButton::clicked, this, &ExportDialog::startExport);
    connect(m_showFolder, &QPushButton::clicked, this, [this] {
        QDesktopServices::openUrl(QUrl::fromLocalFile(QFileInfo(m_output->text()).absolutePath()));
    });
    connect(m_cancel, &QPushButton::clicked, this, [this] {
        if (m_job.isRunning())
            cancelExport();
        else
            reject();
    });
    connect(&m_job, &jobs::BackgroundJob::finished, this, &ExportDialog::onFinished);
    m_poll.setInterval(100);
    connect(&m_poll, &QTimer::timeout, this, &ExportDialog::pollProgress);
    setCapture(capturePath);
}

ExportDialog::~ExportDialog()
{
    // As in TwistAlignDialog: the field's editingFinished on the hide in QDialog's destructor.
    disconnect(m_captureEdit, nullptr, this, nullptr);
    // m_job cancels and joins a running export.
}

void ExportDialog::setCapture(const QString &path)
{
    // A session by its folder or its session.json.
    const QFileInfo info(path);
    QString capture = path;
    if (info.fileName() == QLatin1String(record::SessionManifest::kFileName))
        capture = info.absolutePath();
    m_session = record::SessionManifest::isSessionFolder(capture);
    m_capture = capture;
    m_captureEdit->setText(capture);
    setWindowTitle(m_session ? tr("Export the session %1").arg(QFileInfo(capture).fileName())
                             : tr("Export %1").arg(info.fileName()));
    // A session is exported whole, its devices on one time base, in the formats that hold
    // several devices (the vendor's CSV is one module's layout).
    const int vendor = m_format->findData(int(Format::VendorCsv));
    if (auto *model = qobject_cast<QStandardItemModel *>(m_format->model()))
        if (QStandardItem *item = model->item(vendor))
            item->setEnabled(!m_session);
    if (m_session && m_format->currentIndex() == vendor)
        m_format->setCurrentIndex(m_format->findData(int(Format::TidyCsv)));
    m_from->setEnabled(!m_session);
    m_to->setEnabled(!m_session);
    const QString whole = tr("A recorded session is exported whole, every device aligned on the session's time base");
    m_from->setToolTip(m_session ? whole : QString());
    m_to->setToolTip(m_session ? whole : QString());
    suggestOutput();
}

void ExportDialog::chooseCapture()
{
    const QString path = QFileDialog::getOpenFileName(
        this, tr("Export capture"), m_session ? m_capture : QFileInfo(m_capture).absolutePath(),
        tr("Captures, sessions, vendor CSV and raw dumps (*.imucap session.json *.csv *.bin *.raw *.log *.dat *.txt);;All files (*)"));
    if (!path.isEmpty())
        setCapture(path);
}

void ExportDialog::setFormat(Format format)
{
    m_format->setCurrentIndex(m_format->findData(int(format)));
}

void ExportDialog::setOutput(const QString &path)
{
    m_output->setText(path);
}

void ExportDialog::setRange(double fromS, double toS)
{
    m_from->setValue(fromS);
    m_to->setValue(toS < 0 ? -1 : toS);
}

void ExportDialog::suggestOutput()
{
    const QFileInfo info(m_capture);
    const auto format = Format(m_format->currentData().toInt());
    if (m_session) // beside the folder, named after it (as imudesk-cli export FOLDER does)
        m_output->setText(QDir::cleanPath(info.absoluteFilePath()) + record::CaptureExporter::extension(format));
    else
        m_output->setText(info.path() + QLatin1Char('/') + info.completeBaseName()
                          + record::CaptureExporter::extension(format));
}

void ExportDialog::startExport()
{
    if (m_job.isRunning())
        return;
    if (m_captureEdit->text() != m_capture) // typed, and Export pressed without leaving the field
        setCapture(m_captureEdit->text());
    record::CaptureExporter::Options o;
    o.format = Format(m_format->currentData().toInt());
    o.output = m_output->text();
    o.fromS = m_from->value();
    if (m_to->value() >= 0)
        o.toS = m_to->value();
    m_progress->setValue(0);
    m_status->setText(tr("Exporting…"));
    m_export->setEnabled(false);
    m_captureEdit->setEnabled(false);
    m_chooseCapture->setEnabled(false);
    m_showFolder->hide();
    m_cancel->setText(tr("Cancel"));
    const QString capture = m_capture;
    if (m_session) {
        m_progress->setRange(0, 0); // the session's exporter tells no fraction: busy until done
        record::SessionExporter::Options so;
        so.format = o.format;
        so.output = o.output;
        m_job.launch(QStringLiteral("imudesk-export"), [this, capture, so](const jobs::BackgroundJob::Context &job) mutable {
            so.cancelled = [&job] { return job.cancelled(); };
            const auto r = record::SessionExporter::run(capture, so);
            record::CaptureExporter::Result result;
            result.ok = r.ok;
            result.error = r.error;
            result.cancelled = job.cancelled() && !r.ok;
            result.frames = r.rows;
            if (r.ok)
                result.files << so.output;
            result.notes = r.notes;
            jobs::BackgroundJob::Outcome outcome{result.ok, result.error, {}};
            outcome.apply = [this, result = std::move(result)] { m_result = result; };
            return outcome;
        });
        m_poll.start();
        return;
    }
    m_job.launch(QStringLiteral("imudesk-export"), [this, capture, o](const jobs::BackgroundJob::Context &job) {
        auto result = record::CaptureExporter::run(capture, o, [&job](double f) {
            job.setProgress(f);
            return !job.cancelled();
        });
        jobs::BackgroundJob::Outcome outcome{result.ok, result.error, {}};
        // Stored in the dialog's thread, after the worker has ended.
        outcome.apply = [this, result = std::move(result)] { m_result = result; };
        return outcome;
    });
    m_poll.start();
}

void ExportDialog::cancelExport()
{
    m_job.cancel();
}

void ExportDialog::pollProgress()
{
    m_progress->setValue(int(m_job.progress() * 1000));
}

void ExportDialog::onFinished()
{
    m_poll.stop();
    m_progress->setRange(0, 1000);
    m_export->setEnabled(true);
    m_captureEdit->setEnabled(true);
    m_chooseCapture->setEnabled(true);
    QString message;
    if (m_result.cancelled) {
        message = tr("Export cancelled; the partial files were removed.");
        m_progress->setValue(0);
    } else if (!m_result.ok) {
        message = m_result.error;
    } else {
        m_progress->setValue(1000);
        // Done: nothing is left to cancel. Close, or look at what was written (Export again
        // writes another format or range).
        m_cancel->setText(tr("Close"));
        m_showFolder->show();
        message = tr("%n row(s) written to %1", nullptr, int(std::min<uint64_t>(m_result.frames, INT32_MAX)))
                      .arg(m_result.files.join(QStringLiteral(", ")));
        for (const QString &note : m_result.notes)
            message += QLatin1Char('\n') + note;
        if (!m_result.warning.isEmpty())
            message += QLatin1Char('\n') + m_result.warning;
    }
    m_status->setText(message);
    Q_EMIT exportFinished(m_result.ok, message);
}

} // namespace imudesk::ui
