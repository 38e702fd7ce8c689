#pragma once
// Reads a capture file (capture/capture_format.h) chunk by chunk with a bounded buffer.
// A file that ends inside a chunk (the writer was killed, the cable pulled, the disk
// filled) reads up to its last complete chunk and reports Truncated; a chunk whose CRC
// or framing is wrong is reported as Damaged and the next call searches for the next
// valid chunk after it, so one bad sector costs only the chunks it touched.
#include "capture/capture_format.h"
#include "capture/capture_header.h"

#include <QCoreApplication>
#include <QIODevice>
#include <QString>

#include <cstdint>
#include <memory>
#include <vector>

namespace imudesk::capture {

class CaptureReader {
    Q_DECLARE_TR_FUNCTIONS(CaptureReader)

public:
    enum class Result { Chunk, End, Truncated, Damaged, Error };
    struct Chunk {
        capture::ChunkKind kind = capture::ChunkReceived;
        int64_t monotonicNs = 0;
        int64_t wallUs = 0;
        const uint8_t *data = nullptr; // valid until the next call
        size_t size = 0;
        qint64 offset = 0;             // file offset of the chunk
    };

    CaptureReader();
    ~CaptureReader();

    // Opens a file and reads its header.
    bool open(const QString &path, QString *error);
    // Reads from a device already open for reading (the reader does not own it).
    bool open(QIODevice *device, QString *error);
    void close();

    const CaptureHeader &header() const { return m_header; }
    // Next chunk. After Damaged, call again to continue after the damage; End, Truncated
    // and Error are final. message() says what happened for anything but Chunk and End.
    Result next(Chunk &chunk);
    QString message() const { return m_message; }

    qint64 dataStart() const { return m_dataStart; }
    qint64 size() const;
    qint64 position() const { return m_bufOffset + qint64(m_pos); }
    // Continues reading at a chunk offset (from Chunk::offset or dataStart()).
    bool seek(qint64 offset);
    uint64_t damagedChunks() const { return m_damaged; }

    // Is this a capture file? (Reads the magic only.)
    static bool looksLikeCapture(const QString &path);

private:
    bool fill(size_t need); // at least need bytes buffered from m_pos (false at end of file)
    bool readHeader(QString *error);

    std::unique_ptr<QIODevice> m_owned;
    QIODevice *m_device = nullptr;
    CaptureHeader m_header;
    std::vector<uint8_t> m_buf;
    size_t m_pos = 0;        // read position in m_buf
    size_t m_len = 0;        // valid bytes in m_buf
    qint64 m_bufOffset = 0;  // file offset of m_buf[0]
    qint64 m_dataStart = 0;
    bool m_eof = false;
    bool m_final = false;
    Result m_finalResult = Result::End;
    bool m_resync = false;   // the last chunk was damaged: search for the next magic
    uint64_t m_damaged = 0;
    QString m_message;
};

} // namespace imudesk::capture
