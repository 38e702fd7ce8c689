#pragma once
// The report of one calibration run (issue 6, "Calibration history"): a QTextDocument
// (HTML) with the title, device, firmware, time, kind, the verdict and its reason, the
// metrics with their units, for magnetometer runs the sphere of the samples before and
// after the run's hard/soft-iron correction (read out and captioned with the run's own
// figures), the device's own calibration as a section of its own when it was run (MagSphereView rendered into a QImage and
// added as the document's image resource kSphereUrl), and when the verdict is fail or
// warn the troubleshooting of the v1.7.1 manual's chapter 9 (9.31 steps, 9.32 causes).
// writePdf() prints it with QPdfWriter (QtGui only) into memory and then to the file, so
// an unwritable path or a full disk comes back as a message, never a half-written file.
#include "calib/calibration_history.h"
#include "calib/sample_csv.h"

#include <Eigen/Core>

#include <QCoreApplication>
#include <QImage>
#include <QList>
#include <QPair>
#include <QString>
#include <QUrl>

#include <memory>
#include <vector>

QT_BEGIN_NAMESPACE
class QTextDocument;
QT_END_NAMESPACE

namespace imudesk::ui {

class CalibrationReport {
    Q_DECLARE_TR_FUNCTIONS(CalibrationReport)

public:
    static constexpr int kSphereSize = 420;   // pixels per sphere in the picture

    CalibrationReport(calib::CalibrationRecord record, calib::SampleTable samples);
    ~CalibrationReport();

    static QUrl sphereUrl();
    // (label with unit, value) of every metric in a run's result, in a fixed order for the
    // known keys, then any others; verdict and reason are not among them.
    static QList<QPair<QString, QString>> metrics(const calib::CalibrationRecord &record);
    // The device's own calibration of a run (result key "device_calibration", written by the
    // magnetometer wizard when it ran the module's MCAL): its verdict word, message and last
    // STAT/PROGRESS; empty when the device's calibration was not run.
    static QString deviceVerdictText(const calib::CalibrationRecord &record);
    // The translated word for a verdict ("pass" ...).
    static QString verdictText(const QString &verdict);
    // The magnetometer samples of a table (empty when it has no mag_x/y/z columns).
    static std::vector<Eigen::Vector3d> magSamples(const calib::SampleTable &samples);

    const calib::CalibrationRecord &record() const { return m_record; }
    // Before (raw) and, when the run has a usable correction, after: side by side.
    // Null for runs without magnetometer samples.
    const QImage &sphereImage() const { return m_sphere; }
    QTextDocument &document() { return *m_document; }
    QString html() const { return m_html; }
    QString plainText() const;
    // The caption under the sphere: what the picture shows, with the run's sample count and
    // coverage (empty without a picture).
    QString sphereCaption() const;

    // false with *error (translated: what happened and what to do).
    bool writePdf(const QString &path, QString *error = nullptr);

private:
    void renderSphere();
    void buildHtml();
    // The device's own run (result key "device_calibration"), when the wizard ran it.
    void deviceSection(QString &h) const;

    calib::CalibrationRecord m_record;
    calib::SampleTable m_samples;
    QImage m_sphere;
    QString m_html;
    std::unique_ptr<QTextDocument> m_document;
};

} // namespace imudesk::ui
