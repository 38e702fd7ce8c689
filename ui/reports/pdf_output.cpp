#include "reports/pdf_output.h"

#include <QBuffer>
#include <QDir>
#include <QPageLayout>
#include <QPageSize>
#include <QPdfWriter>
#include <QSaveFile>
#include <QTextDocument>

namespace imudesk::ui {

bool PdfOutput::write(QTextDocument &document, const QString &title, const QString &path, QString *error)
{
    auto failWith = [error](const QString &m) {
        if (error)
            *error = m;
        return false;
    };
    if (path.isEmpty())
        return failWith(tr("No file name was given for the report."));
    QBuffer buffer;
    buffer.open(QIODevice::WriteOnly);
    {
        QPdfWriter writer(&buffer);
        writer.setResolution(kResolution);
        writer.setPageSize(QPageSize(QPageSize::A4));
        writer.setPageMargins(QMarginsF(15, 15, 15, 15), QPageLayout::Millimeter);
        writer.setTitle(title);
        writer.setCreator(QStringLiteral("ImuDesk"));
        document.print(&writer);
    }
    buffer.close();
    if (!buffer.data().startsWith("%PDF"))
        return failWith(tr("The report could not be rendered as PDF."));
    QSaveFile file(path);
    if (!file.open(QIODevice::WriteOnly))
        return failWith(tr("Cannot write the report to %1: %2. Choose another folder.")
                            .arg(QDir::toNativeSeparators(path), file.errorString()));
    if (file.write(buffer.data()) != buffer.data().size() || !file.commit())
        return failWith(tr("Cannot write the report to %1: %2. Check the free disk space and try again.")
                            .arg(QDir::toNativeSeparators(path), file.errorString()));
    return true;
}

} // namespace imudesk::ui
