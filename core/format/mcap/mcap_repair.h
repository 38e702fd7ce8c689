#pragma once
// Completes an MCAP file that was not closed (a recording killed, a full disk, a cable pulled
// with the power): every record up to the first one cut short is read — schemas, channels and
// messages inside and outside chunks, attachments, metadata — and written again through
// McapWriter, which adds the message indexes, the summary and the footer. What followed the
// last whole record is left out (and counted). A file that is complete already is rewritten
// the same way (its summary recomputed). `imudesk-cli repair`.
#include <QIODevice>
#include <QString>

#include <cstdint>

namespace imudesk::format::mcap {

struct RepairResult {
    bool ok = false;
    QString error;
    bool notMcap = false;       // the input does not start with MCAP's magic
    bool wasComplete = false;   // the input had its data end (and so its summary)
    uint64_t messages = 0;      // messages written to the output
    uint64_t chunksRead = 0;    // whole chunks read
    uint64_t bytesLeftOut = 0;  // the cut record at the end, and anything after it
    uint64_t firstTimeNs = 0, lastTimeNs = 0; // log times of the messages kept
};

// out must differ from in.
RepairResult repairMcap(const QString &in, const QString &out);
// The same from an open device (read from its start; the fuzz target's QBuffer).
RepairResult repairMcap(QIODevice &in, const QString &out);

} // namespace imudesk::format::mcap
