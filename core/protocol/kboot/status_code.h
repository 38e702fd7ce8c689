#pragma once
// KBOOT status codes (NXP MCUBoot reference manual, "status and error codes"), as sent in
// GenericResponse, GetPropertyResponse and ReadMemoryResponse.
#include <QCoreApplication>
#include <QString>

#include <cstdint>

namespace imudesk::protocol::kboot {

enum StatusCode : uint32_t {
    kStatusSuccess = 0,
    kStatusFail = 1,
    kStatusReadOnly = 2,
    kStatusOutOfRange = 3,
    kStatusInvalidArgument = 4,
    kStatusTimeout = 5,
    kStatusNoTransferInProgress = 6,
    kStatusFlashSizeError = 100,
    kStatusFlashAlignmentError = 101,
    kStatusFlashAddressError = 102,
    kStatusFlashAccessError = 103,
    kStatusFlashProtectionViolation = 104,
    kStatusFlashCommandFailure = 105,
    kStatusFlashUnknownProperty = 106,
    kStatusFlashEraseKeyError = 107,
    kStatusFlashRegionExecuteOnly = 108,
    kStatusUnknownCommand = 10000,
    kStatusSecurityViolation = 10001,
    kStatusAbortDataPhase = 10002,
    kStatusPingError = 10003,
    kStatusNoResponse = 10004,
    kStatusNoResponseExpected = 10005,
    kStatusUnsupportedCommand = 10006,
    kStatusMemoryRangeInvalid = 10200,
    kStatusMemoryReadFailed = 10201,
    kStatusMemoryWriteFailed = 10202,
    kStatusMemoryCumulativeWrite = 10203,
    kStatusUnknownProperty = 10300,
    kStatusReadOnlyProperty = 10301,
    kStatusInvalidPropertyValue = 10302,
    kStatusAppCrcCheckPassed = 10400,
    kStatusAppCrcCheckFailed = 10401,
    kStatusAppCrcCheckInactive = 10402,
    kStatusAppCrcCheckInvalid = 10403,
    kStatusAppCrcCheckOutOfRange = 10404,
    kStatusNoPingResponse = 10500,
    kStatusInvalidPacketType = 10501,
    kStatusInvalidCrc = 10502,
    kStatusNoCommandResponse = 10503,
};

class KbootStatus {
    Q_DECLARE_TR_FUNCTIONS(KbootStatus)

public:
    // "<name> (<code>): <meaning>"; unknown codes are shown with their number.
    static QString message(uint32_t status);
    // The KBOOT name ("kStatus_FlashAlignmentError"); empty when unknown.
    static const char *name(uint32_t status);
};

} // namespace imudesk::protocol::kboot
