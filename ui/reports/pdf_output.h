#pragma once
// Prints a QTextDocument as an A4 PDF (QPdfWriter, QtGui only) into memory and then to the
// file with QSaveFile, so an unwritable path or a full disk comes back as a message and never
// leaves a half-written file. Shared by the calibration and station reports.
#include <QCoreApplication>
#include <QString>

QT_BEGIN_NAMESPACE
class QTextDocument;
QT_END_NAMESPACE

namespace imudesk::ui {

class PdfOutput {
    Q_DECLARE_TR_FUNCTIONS(imudesk::ui::PdfOutput)

public:
    static constexpr int kResolution = 300; // dpi

    // false with *error (translated: what happened and what to do).
    static bool write(QTextDocument &document, const QString &title, const QString &path, QString *error);
};

} // namespace imudesk::ui
