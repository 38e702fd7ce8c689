#include "capture_source.h"

#include "capture/capture_format.h"
#include "capture/converted_capture.h"
#include "decode/file_import.h"

#include <QFile>
#include <QFileInfo>
#include <QTemporaryDir>

namespace imudesk::record {

namespace {

CaptureSource::Kind kindOf(const decode::FileImporter &importer)
{
    switch (importer.kind()) {
    case decode::FileImporter::Kind::VendorCsv: return CaptureSource::Kind::VendorCsv;
    case decode::FileImporter::Kind::RawDump: return CaptureSource::Kind::RawDump;
    }
    return CaptureSource::Kind::Unknown;
}

} // namespace

CaptureSource::CaptureSource() = default;
CaptureSource::~CaptureSource() = default;

const char *CaptureSource::kindName(Kind k)
{
    switch (k) {
    case Kind::Capture: return "capture";
    case Kind::VendorCsv: return "vendor CSV";
    case Kind::RawDump: return "raw byte dump";
    case Kind::Unknown: break;
    }
    return "unknown";
}

const decode::FileImporter *CaptureSource::importerOf(const QString &path, Kind *kind, QString *error)
{
    *kind = Kind::Unknown;
    QFile f(path);
    if (!f.open(QIODevice::ReadOnly)) {
        if (error)
            *error = tr("%1 cannot be read: %2").arg(path, f.errorString());
        return nullptr;
    }
    const QByteArray head = f.read(decode::kSniffBytes);
    if (head.isEmpty()) {
        if (error)
            *error = tr("%1 is empty").arg(path);
        return nullptr;
    }
    if (head.startsWith(QByteArray(capture::kMagic, sizeof capture::kMagic))) {
        *kind = Kind::Capture;
        return nullptr;
    }
    if (const decode::FileImporter *importer = decode::fileImporterFor(head, f.atEnd())) {
        *kind = kindOf(*importer);
        return importer;
    }
    if (error) {
        QStringList what;
        for (const decode::FileImporter *i : decode::fileImporters())
            what << i->looksLike();
        const QString last = what.isEmpty() ? QString() : what.takeLast();
        *error = what.isEmpty() ? tr("%1 is neither an ImuDesk capture nor %2").arg(path, last)
                                : tr("%1 is neither an ImuDesk capture, %2 nor %3")
                                      .arg(path, what.join(QStringLiteral(", ")), last);
    }
    return nullptr;
}

CaptureSource::Kind CaptureSource::detect(const QString &path, QString *error)
{
    Kind kind = Kind::Unknown;
    importerOf(path, &kind, error);
    return kind;
}

CaptureSource::Converted CaptureSource::convert(const QString &path, const QString &capturePath)
{
    Converted c;
    const decode::FileImporter *importer = importerOf(path, &c.kind, &c.error);
    if (!importer) {
        if (c.kind == Kind::Capture)
            c.error = tr("%1 is already an ImuDesk capture").arg(path);
        return c;
    }
    return convertWith(*importer, c.kind, path, capturePath);
}

CaptureSource::Converted CaptureSource::convertWith(const decode::FileImporter &importer, Kind kind,
                                                    const QString &path, const QString &capturePath)
{
    Converted c;
    c.kind = kind;
    capture::CaptureHeader header;
    if (importer.times() == decode::FileImporter::Times::PcCounter) {
        header.set(capture::CaptureHeader::kPcCounter, "chunk time");
    } else {
        header.set(capture::CaptureHeader::kHostTime, "absent");
        // No pause was recorded: like `imudesk-cli decode`, only the end of the file releases
        // held bytes.
        header.set(capture::CaptureHeader::kIdleMarkers, "1");
    }
    capture::ConvertedCapture out;
    if (!out.open(capturePath, path, importer.linkKind(), importer.family(), header, &c.error))
        return c;
    c.import = importer.convert(path, out);
    const decode::FileImporter::Result &r = c.import;
    if (!r.ok) {
        out.discard();
        c.error = r.error;
        return c;
    }
    if (!out.finish(&c.error))
        return c;
    const QString name = QFileInfo(path).fileName();
    if (c.kind == Kind::VendorCsv) {
        c.notes << tr("%1 is a vendor CSV: %n row(s) read, times from its pc_counter column", nullptr, int(r.rows))
                       .arg(name);
        c.notes << r.lineErrors;
        if (r.badLines > uint64_t(r.lineErrors.size()))
            c.notes << tr("%1 malformed lines in all").arg(r.badLines);
    } else {
        c.notes << (r.deviceClock ? tr("%1 is a raw byte dump without arrival times: the times shown come from the "
                                       "device's own clock")
                                  : tr("%1 is a raw byte dump without arrival times, and nothing in it carries a "
                                       "device time: every time is 0"))
                       .arg(name);
        if (r.clockJumps > 0)
            c.notes << tr("The device clock restarted or jumped %n time(s); the times go on across each jump.", nullptr,
                          int(r.clockJumps));
    }
    c.ok = true;
    return c;
}

bool CaptureSource::prepare(const QString &path, QString *error)
{
    m_notes.clear();
    m_temp.reset();
    m_capturePath.clear();
    QString why;
    const decode::FileImporter *importer = importerOf(path, &m_kind, &why); // the file's head read once
    if (m_kind == Kind::Unknown) {
        if (error)
            *error = why;
        return false;
    }
    if (m_kind == Kind::Capture) {
        m_capturePath = path;
        return true;
    }
    m_temp = std::make_unique<QTemporaryDir>();
    if (!m_temp->isValid()) {
        if (error)
            *error = tr("No temporary folder to convert %1 in: %2").arg(path, m_temp->errorString());
        return false;
    }
    const QString converted = m_temp->filePath(QFileInfo(path).completeBaseName() + QStringLiteral(".imucap"));
    const Converted c = convertWith(*importer, m_kind, path, converted);
    if (!c.ok) {
        if (error)
            *error = c.error;
        return false;
    }
    m_notes = c.notes;
    m_capturePath = converted;
    return true;
}

} // namespace imudesk::record
