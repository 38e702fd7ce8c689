#pragma once
// A family's own files that ImuDesk reads as if they were captures (issue 54): a CSV its vendor's
// tool writes, a raw dump of what its module sent. Each importer recognises its files by their
// first bytes, never their name, and turns one into what a capture holds (the bytes the family's
// decoder reads, chunk by chunk, each with a time) through a ChunkSink. record/capture_source.h
// writes the capture and knows no family: it asks fileImporterFor(head).
#include <QString>
#include <QStringList>

#include <cstddef>
#include <cstdint>
#include <vector>

class QByteArray;

namespace imudesk::decode {

// Where an importer's chunks go (capture/converted_capture.h writes them to a capture).
class ChunkSink {
public:
    enum class Role {
        Received,  // bytes as the device sent them, for the family's decoder
        KeptCells, // cells of a vendor row its record cannot give back (VendorLayout::Cells)
    };
    virtual ~ChunkSink() = default;
    virtual void chunk(int64_t ns, const uint8_t *data, size_t n, Role role = Role::Received) = 0;
};

class FileImporter {
public:
    enum class Kind { VendorCsv, RawDump };
    // The times its chunks carry.
    enum class Times {
        PcCounter,   // the vendor tool's arrival times (its pc_counter column)
        DeviceClock, // none recorded: the device's own clock where the bytes carry one, else 0
    };
    struct Result {
        bool ok = false;
        QString error;
        uint64_t rows = 0;         // a vendor CSV's rows read (each one record)
        uint64_t badLines = 0;     // its malformed lines, left out
        QStringList lineErrors;    // the first of them, each with its line number
        uint64_t bytes = 0;        // a raw dump's bytes
        uint64_t frames = 0;       // CRC-valid frames found in them
        uint64_t sentences = 0;    // NMEA sentences with a valid checksum
        uint64_t clockJumps = 0;   // device clock restarts or jumps the times were carried across
        bool deviceClock = false;  // DeviceClock times: something in the file carried a time
    };

    virtual ~FileImporter() = default;
    virtual Kind kind() const = 0;
    virtual Times times() const = 0;
    // The family whose decoder reads the capture (CaptureHeader::kFamily) and the capture's link
    // kind, which names where it came from ("vendor CSV import", "raw byte dump").
    virtual const char *family() const = 0;
    virtual const char *linkKind() const = 0;
    // Is this one of its files? head: its first bytes (up to kSniffBytes); whole: that is all of it.
    virtual bool recognises(const QByteArray &head, bool whole) const = 0;
    // What its files look like, for a file that no importer takes ("a vendor CSV (first line
    // "HI91,...")"; translated).
    virtual QString looksLike() const = 0;
    // Writes the file's chunks to out; false in Result::ok with why (nothing is valid then).
    virtual Result convert(const QString &path, ChunkSink &out) const = 0;
};

constexpr int64_t kSniffBytes = 64 * 1024;

// Every importer, in the order they are asked; the first that recognises a file takes it.
const std::vector<const FileImporter *> &fileImporters();
const FileImporter *fileImporterFor(const QByteArray &head, bool whole);

} // namespace imudesk::decode
