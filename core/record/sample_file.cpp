#include "sample_file.h"

#include "capture/capture_decoder.h"
#include "capture/capture_reader.h"
#include "record/capture_source.h"
#include "record/session_manifest.h"

#include <QDir>
#include <QFileInfo>

namespace imudesk::record {

SampleFile::Opened SampleFile::forEachCaptureSample(const QString &path,
                                                    const std::function<void(const model::Sample &)> &onSample)
{
    Opened r;
    CaptureSource source;
    if (!source.prepare(path, &r.error))
        return r;
    r.kind = QString::fromLatin1(CaptureSource::kindName(source.kind()));
    r.notes << source.notes();
    capture::CaptureReader reader;
    if (!reader.open(source.capturePath(), &r.error))
        return r;
    struct Sink : capture::CaptureDecoder::Sink {
        const std::function<void(const model::Sample &)> *fn = nullptr;
        void onSample(const model::Sample &s, const decode::Record &) override { (*fn)(s); }
    } sink;
    sink.fn = &onSample;
    capture::CaptureDecoder decoder;
    if (!decoder.configure(reader.header())) {
        r.error = decoder.error();
        return r;
    }
    capture::CaptureReader::Chunk c;
    capture::CaptureReader::Result res;
    while ((res = reader.next(c)) == capture::CaptureReader::Result::Chunk || res == capture::CaptureReader::Result::Damaged)
        if (res == capture::CaptureReader::Result::Chunk)
            decoder.feedChunk(c, sink);
    decoder.finish(sink);
    if (res == capture::CaptureReader::Result::Truncated)
        r.notes << reader.message();
    r.ok = true;
    return r;
}

SampleFile::Opened SampleFile::forEachSample(const QString &path, const QString &device,
                                             const std::function<void(const model::Sample &)> &onSample)
{
    if (!QFileInfo(path).isDir()) {
        if (!device.isEmpty() && CaptureSource::detect(path) != CaptureSource::Kind::Capture) {
            Opened r;
            r.error = tr("--device chooses a device of a session: %1 is not one").arg(QDir::toNativeSeparators(path));
            return r;
        }
        return forEachCaptureSample(path, onSample);
    }
    Opened r;
    if (!SessionManifest::isSessionFolder(path)) {
        r.error = tr("%1 is a folder without session.json: give a file, or a recorded session's folder")
                      .arg(QDir::toNativeSeparators(path));
        return r;
    }
    SessionManifest manifest;
    if (!SessionManifest::load(path, &manifest, &r.error))
        return r;
    QStringList names;
    const SessionManifest::Device *chosen = nullptr;
    for (const auto &d : manifest.devices) {
        names << d.name;
        if (d.name == device)
            chosen = &d;
    }
    if (!device.isEmpty() && !chosen) {
        r.error = tr("the session %1 has no device %2; its devices: %3")
                      .arg(QDir::toNativeSeparators(path), device, names.join(QStringLiteral(", ")));
        return r;
    }
    if (!chosen) {
        if (manifest.devices.size() != 1) {
            r.error = tr("the session %1 holds %2 devices (%3): choose one with --device NAME")
                          .arg(QDir::toNativeSeparators(path))
                          .arg(manifest.devices.size())
                          .arg(names.join(QStringLiteral(", ")));
            return r;
        }
        chosen = &manifest.devices.front();
    }
    r = forEachCaptureSample(QDir(path).filePath(chosen->file), onSample);
    r.kind = tr("session");
    r.device = chosen->name;
    return r;
}

} // namespace imudesk::record
