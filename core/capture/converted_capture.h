#pragma once
// A capture written in one go by a converter (a vendor CSV, a raw byte dump: decode/file_import.h):
// the header, then received-bytes chunks gathered in 1 MB blocks. A failed write is kept and
// reported once, by finish(), which removes the partial file then.
#include "capture/capture_format.h"
#include "capture/capture_header.h"
#include "decode/file_import.h"

#include <QCoreApplication>
#include <QFile>
#include <QString>

#include <cstdint>
#include <vector>

namespace imudesk::capture {

class ConvertedCapture : public decode::ChunkSink {
    Q_DECLARE_TR_FUNCTIONS(ConvertedCapture)

public:
    // Creates path with a header naming the link kind and the source file; header's keys are
    // added. False with a message when the file cannot be written.
    bool open(const QString &path, const QString &sourcePath, const char *linkKind, const char *family,
              const capture::CaptureHeader &header,
              QString *error);
    void append(int64_t monotonicNs, const uint8_t *data, size_t n, capture::ChunkKind kind = capture::ChunkReceived);
    // An importer's chunk: received bytes, or a vendor row's kept cells (ChunkVendorCells).
    void chunk(int64_t ns, const uint8_t *data, size_t n, Role role = Role::Received) override
    {
        append(ns, data, n, role == Role::KeptCells ? capture::ChunkVendorCells : capture::ChunkReceived);
    }
    // Writes what is buffered and closes; false (file removed) with a message when a write failed.
    bool finish(QString *error);
    // Closes and removes the file (the conversion failed).
    void discard();

private:
    void flush();

    QFile m_file;
    std::vector<uint8_t> m_buf;
    bool m_failed = false;
};

} // namespace imudesk::capture
