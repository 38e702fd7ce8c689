#include "calibration/calibration_history_dialog.h"

#include "calib/mag_cal_result.h"
#include "calibration/calibration_report.h"
#include "calibration/mag_sphere_view.h"
#include "itemmodels/calibration_history_model.h"

#include <QDesktopServices>
#include <QDialogButtonBox>
#include <QDir>
#include <QFileDialog>
#include <QGridLayout>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QListWidget>
#include <QLoggingCategory>
#include <QMessageBox>
#include <QPushButton>
#include <QSaveFile>
#include <QScrollArea>
#include <QSettings>
#include <QSplitter>
#include <QTableView>
#include <QTextDocument>
#include <QUrl>
#include <QVBoxLayout>

Q_LOGGING_CATEGORY(lcCalHistory, "imudesk.ui.calhistory")

namespace imudesk::ui {

CalibrationHistoryDialog::CalibrationHistoryDialog(const QString &root, QWidget *parent)
    : QDialog(parent),
      m_history(root)
{
    setWindowTitle(tr("Calibration history"));
    setObjectName(QStringLiteral("calibrationHistoryDialog"));

    m_devices = new QListWidget;
    m_devices->setToolTip(tr("Devices with calibration runs (by serial number)"));
    m_model = new models::CalibrationHistoryModel(this);
    m_runs = new QTableView;
    m_runs->setModel(m_model);
    m_runs->setSelectionBehavior(QAbstractItemView::SelectRows);
    m_runs->setSelectionMode(QAbstractItemView::SingleSelection);
    m_runs->setEditTriggers(QAbstractItemView::NoEditTriggers);
    m_runs->verticalHeader()->hide();
    m_runs->horizontalHeader()->setStretchLastSection(true);

    m_details = new QLabel;
    m_details->setWordWrap(true);
    m_details->setTextFormat(Qt::RichText);
    m_details->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_details->setAlignment(Qt::AlignLeft | Qt::AlignTop);
    auto *detailsScroll = new QScrollArea;
    detailsScroll->setWidget(m_details);
    detailsScroll->setWidgetResizable(true);

    m_sphereCaption = new QLabel;
    m_sphereCaption->setWordWrap(true);
    m_before = new MagSphereView;
    m_after = new MagSphereView;
    auto *spheres = new QWidget;
    auto *sphereLayout = new QGridLayout(spheres);
    sphereLayout->setContentsMargins(0, 0, 0, 0);
    sphereLayout->addWidget(new QLabel(tr("Before (raw samples)")), 0, 0);
    sphereLayout->addWidget(new QLabel(tr("After (corrected by this run)")), 0, 1);
    sphereLayout->addWidget(m_before, 1, 0);
    sphereLayout->addWidget(m_after, 1, 1);
    sphereLayout->addWidget(m_sphereCaption, 2, 0, 1, 2);
    spheres->setObjectName(QStringLiteral("sphereBox"));

    auto *detailsBox = new QWidget;
    auto *detailsLayout = new QHBoxLayout(detailsBox);
    detailsLayout->setContentsMargins(0, 0, 0, 0);
    detailsLayout->addWidget(detailsScroll, 2);
    detailsLayout->addWidget(spheres, 3);

    auto *right = new QSplitter(Qt::Vertical);
    right->addWidget(m_runs);
    right->addWidget(detailsBox);
    right->setStretchFactor(0, 1);
    right->setStretchFactor(1, 2);
    auto *split = new QSplitter(Qt::Horizontal);
    split->addWidget(m_devices);
    split->addWidget(right);
    split->setStretchFactor(1, 4);
    split->setSizes({170, 830});
    right->setSizes({200, 480});

    m_exportReport = new QPushButton(tr("Export report (PDF)…"));
    m_exportSamples = new QPushButton(tr("Export samples (CSV)…"));
    m_openFolder = new QPushButton(tr("Open folder"));
    m_delete = new QPushButton(tr("Delete"));
    auto *buttons = new QDialogButtonBox(QDialogButtonBox::Close);
    buttons->addButton(m_exportReport, QDialogButtonBox::ActionRole);
    buttons->addButton(m_exportSamples, QDialogButtonBox::ActionRole);
    buttons->addButton(m_openFolder, QDialogButtonBox::ActionRole);
    buttons->addButton(m_delete, QDialogButtonBox::DestructiveRole);

    auto *layout = new QVBoxLayout(this);
    layout->addWidget(split, 1);
    layout->addWidget(buttons);

    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    connect(m_devices, &QListWidget::currentRowChanged, this, &CalibrationHistoryDialog::deviceChanged);
    connect(m_runs->selectionModel(), &QItemSelectionModel::currentRowChanged, this,
            &CalibrationHistoryDialog::runChanged);
    connect(m_exportReport, &QPushButton::clicked, this, &CalibrationHistoryDialog::chooseReportPath);
    connect(m_exportSamples, &QPushButton::clicked, this, &CalibrationHistoryDialog::chooseSamplesPath);
    connect(m_openFolder, &QPushButton::clicked, this, &CalibrationHistoryDialog::openFolder);
    connect(m_delete, &QPushButton::clicked, this, &CalibrationHistoryDialog::confirmDelete);

    resize(1000, 680);
    const QByteArray geometry = QSettings().value(QLatin1String(kGeometryKey)).toByteArray();
    if (!geometry.isEmpty())
        restoreGeometry(geometry);
    reload();
}

CalibrationHistoryDialog::~CalibrationHistoryDialog() = default;

void CalibrationHistoryDialog::done(int result)
{
    QSettings().setValue(QLatin1String(kGeometryKey), saveGeometry());
    QDialog::done(result);
}

void CalibrationHistoryDialog::reload()
{
    const QString previous = currentDevice();
    const QSignalBlocker block(m_devices);
    m_devices->clear();
    m_devices->addItems(m_history.devices());
    int row = 0;
    for (int i = 0; i < m_devices->count(); ++i)
        if (m_devices->item(i)->text() == previous)
            row = i;
    if (m_devices->count() > 0)
        m_devices->setCurrentRow(row);
    deviceChanged();
}

bool CalibrationHistoryDialog::selectDevice(const QString &serial)
{
    const QString folder = calib::CalibrationHistory::deviceFolderName(serial);
    for (int i = 0; i < m_devices->count(); ++i) {
        if (m_devices->item(i)->text() == folder) {
            m_devices->setCurrentRow(i);
            return true;
        }
    }
    return false;
}

QString CalibrationHistoryDialog::currentDevice() const
{
    const QListWidgetItem *item = m_devices->currentItem();
    return item ? item->text() : QString();
}

void CalibrationHistoryDialog::deviceChanged()
{
    const QString device = currentDevice();
    if (device.isEmpty())
        m_model->setRecords({});
    else
        m_model->load(m_history, device);
    m_runs->resizeColumnsToContents();
    if (m_model->rowCount() > 0)
        selectRun(0);
    else
        runChanged();
}

bool CalibrationHistoryDialog::selectRun(int row)
{
    if (row < 0 || row >= m_model->rowCount())
        return false;
    m_runs->selectionModel()->setCurrentIndex(m_model->index(row, 0),
                                              QItemSelectionModel::ClearAndSelect | QItemSelectionModel::Rows);
    runChanged();
    return true;
}

const calib::CalibrationRecord *CalibrationHistoryDialog::currentRecord() const
{
    const QModelIndex index = m_runs->selectionModel()->currentIndex();
    if (!index.isValid() || index.row() >= m_model->rowCount())
        return nullptr;
    return &m_model->record(index.row());
}

void CalibrationHistoryDialog::runChanged()
{
    const calib::CalibrationRecord *r = currentRecord();
    m_exportReport->setEnabled(r);
    m_exportSamples->setEnabled(r);
    m_openFolder->setEnabled(r);
    m_delete->setEnabled(r);
    m_samples = {};
    m_before->clear();
    m_after->clear();
    m_after->clearCalibration();
    if (!r) {
        m_details->setText(m_devices->count() == 0
                               ? tr("No calibration runs yet. The calibration wizards keep every finished run "
                                    "here, in %1.")
                                     .arg(QDir::toNativeSeparators(m_history.root()).toHtmlEscaped())
                               : tr("Select a run."));
        m_before->parentWidget()->setVisible(false);
        return;
    }
    QString error;
    if (!m_history.loadSamples(*r, m_samples, &error))
        qCWarning(lcCalHistory) << error;
    auto esc = [](const QString &s) { return s.toHtmlEscaped(); };
    const QString reason = r->result.value(QStringLiteral("reason")).toString();
    QString html = QStringLiteral("<h3>%1</h3><p><b>%2</b> %3<br>%4</p>")
                       .arg(esc(models::CalibrationHistoryModel::kindText(r->kind)),
                            esc(tr("Verdict: %1").arg(CalibrationReport::verdictText(r->verdict()))), esc(reason),
                            esc(tr("%1, serial %2, firmware %3, %4 UTC, %5 samples")
                                    .arg(r->product.isEmpty() ? tr("unknown product") : r->product,
                                         r->deviceSerial.isEmpty() ? tr("unknown") : r->deviceSerial,
                                         r->firmware.isEmpty() ? tr("unknown") : r->firmware,
                                         r->time.toUTC().toString(QStringLiteral("yyyy-MM-dd HH:mm:ss")))
                                    .arg(r->sampleCount)));
    html += QStringLiteral("<table cellspacing=\"0\" cellpadding=\"2\">");
    for (const auto &[label, value] : CalibrationReport::metrics(*r))
        html += QStringLiteral("<tr><td>%1</td><td><b>%2</b></td></tr>").arg(esc(label), esc(value));
    html += QStringLiteral("</table>");
    // The device's own calibration has its own verdict, beside ImuDesk's, not among its metrics.
    const QString device = CalibrationReport::deviceVerdictText(*r);
    if (!device.isEmpty())
        html += QStringLiteral("<p>%1 <b>%2</b></p>").arg(esc(CalibrationReport::tr("Device's verdict:")), esc(device));
    if (!error.isEmpty())
        html += QStringLiteral("<p>%1</p>").arg(esc(tr("The samples could not be read: %1").arg(error)));
    m_details->setText(html);

    const std::vector<Eigen::Vector3d> mags = CalibrationReport::magSamples(m_samples);
    const bool magnetometer = r->kind == QLatin1String("magnetometer") && !mags.empty();
    m_before->parentWidget()->setVisible(magnetometer);
    if (!magnetometer)
        return;
    m_before->clearCalibration();
    m_after->clearCalibration(); // the run shown before may have had one
    m_before->setSamples(mags);
    m_after->setSamples(mags);
    calib::MagCalResult fit;
    const bool known = calib::MagCalResult::fromJson(r->result, fit);
    if (!known) {
        fit = calib::MagCalResult();
        fit.samples = int(mags.size());
    }
    // A finished run: read out with its own figures, no instruction to turn.
    m_before->showRun(fit);
    m_after->showRun(fit);
    if (known && fit.usable()) {
        m_after->setCalibration(fit.hardIron, fit.softIron);
        m_sphereCaption->setText(tr("Right: the same samples corrected by this run's hard and soft iron."));
    } else {
        m_sphereCaption->setText(tr("This run has no usable correction: both spheres show the raw samples."));
    }
}

QString CalibrationHistoryDialog::detailsText() const
{
    QTextDocument doc;
    doc.setHtml(m_details->text());
    return doc.toPlainText();
}

bool CalibrationHistoryDialog::exportReport(const QString &path, QString *error)
{
    const calib::CalibrationRecord *r = currentRecord();
    if (!r) {
        if (error)
            *error = tr("Select a run first.");
        return false;
    }
    CalibrationReport report(*r, m_samples);
    return report.writePdf(path, error);
}

bool CalibrationHistoryDialog::exportSamples(const QString &path, QString *error)
{
    const calib::CalibrationRecord *r = currentRecord();
    auto failWith = [error](const QString &m) {
        if (error)
            *error = m;
        return false;
    };
    if (!r)
        return failWith(tr("Select a run first."));
    calib::SampleTable table;
    QString loadError;
    if (!m_history.loadSamples(*r, table, &loadError))
        return failWith(loadError);
    QSaveFile file(path);
    if (!file.open(QIODevice::WriteOnly))
        return failWith(tr("Cannot write %1: %2. Choose another folder.").arg(QDir::toNativeSeparators(path), file.errorString()));
    const QByteArray data = calib::SampleCsv::write(table);
    if (file.write(data) != data.size() || !file.commit())
        return failWith(tr("Cannot write %1: %2. Check the free disk space and try again.")
                            .arg(QDir::toNativeSeparators(path), file.errorString()));
    return true;
}

bool CalibrationHistoryDialog::removeSelected(QString *error)
{
    const calib::CalibrationRecord *r = currentRecord();
    if (!r || !m_history.remove(*r)) {
        if (error)
            *error = r ? tr("Cannot delete %1: check the folder's permissions.").arg(QDir::toNativeSeparators(r->folder))
                       : tr("Select a run first.");
        return false;
    }
    const int row = m_runs->selectionModel()->currentIndex().row();
    // The device's folder goes with its last run (rmdir removes only an empty folder).
    QDir(m_history.root()).rmdir(currentDevice());
    reload();
    selectRun(std::min(row, m_model->rowCount() - 1));
    return true;
}

void CalibrationHistoryDialog::showError(const QString &message)
{
    QMessageBox::warning(this, windowTitle(), message);
}

void CalibrationHistoryDialog::chooseReportPath()
{
    const calib::CalibrationRecord *r = currentRecord();
    if (!r)
        return;
    const QString name = QStringLiteral("%1-%2-%3.pdf")
                             .arg(calib::CalibrationHistory::deviceFolderName(r->deviceSerial), r->kind,
                                  r->time.toUTC().toString(QStringLiteral("yyyyMMdd-HHmmss")));
    const QString path = QFileDialog::getSaveFileName(this, tr("Export calibration report"),
                                                      QDir::home().filePath(name), tr("PDF files (*.pdf)"));
    QString error;
    if (!path.isEmpty() && !exportReport(path, &error))
        showError(error);
}

void CalibrationHistoryDialog::chooseSamplesPath()
{
    const calib::CalibrationRecord *r = currentRecord();
    if (!r)
        return;
    const QString name = QStringLiteral("%1-%2-%3.csv")
                             .arg(calib::CalibrationHistory::deviceFolderName(r->deviceSerial), r->kind,
                                  r->time.toUTC().toString(QStringLiteral("yyyyMMdd-HHmmss")));
    const QString path = QFileDialog::getSaveFileName(this, tr("Export calibration samples"),
                                                      QDir::home().filePath(name), tr("CSV files (*.csv)"));
    QString error;
    if (!path.isEmpty() && !exportSamples(path, &error))
        showError(error);
}

void CalibrationHistoryDialog::openFolder()
{
    if (const calib::CalibrationRecord *r = currentRecord())
        QDesktopServices::openUrl(QUrl::fromLocalFile(r->folder));
}

void CalibrationHistoryDialog::confirmDelete()
{
    const calib::CalibrationRecord *r = currentRecord();
    if (!r)
        return;
    const auto answer = QMessageBox::question(
        this, tr("Delete calibration run"),
        tr("Delete the %1 run of %2 and its samples? This cannot be undone.\n%3")
            .arg(models::CalibrationHistoryModel::kindText(r->kind),
                 r->time.toLocalTime().toString(QStringLiteral("yyyy-MM-dd HH:mm:ss")),
                 QDir::toNativeSeparators(r->folder)));
    if (answer != QMessageBox::Yes)
        return;
    QString error;
    if (!removeSelected(&error))
        showError(error);
}

} // namespace imudesk::ui
