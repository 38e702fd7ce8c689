#include "file_import.h"

#include "decode/hipnuc_file_import.h"

#include <QByteArray>

namespace imudesk::decode {

const std::vector<const FileImporter *> &fileImporters()
{
    // A vendor CSV is text that could hold an NMEA sentence: it is asked before the raw dump.
    static const HipnucVendorCsvImport vendorCsv;
    static const HipnucRawDumpImport rawDump;
    static const std::vector<const FileImporter *> all = {&vendorCsv, &rawDump};
    return all;
}

const FileImporter *fileImporterFor(const QByteArray &head, bool whole)
{
    for (const FileImporter *i : fileImporters())
        if (i->recognises(head, whole))
            return i;
    return nullptr;
}

} // namespace imudesk::decode
