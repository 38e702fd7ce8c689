#include "status_code.h"

namespace imudesk::protocol::kboot {

const char *KbootStatus::name(uint32_t s)
{
    switch (s) {
    case kStatusSuccess: return "kStatus_Success";
    case kStatusFail: return "kStatus_Fail";
    case kStatusReadOnly: return "kStatus_ReadOnly";
    case kStatusOutOfRange: return "kStatus_OutOfRange";
    case kStatusInvalidArgument: return "kStatus_InvalidArgument";
    case kStatusTimeout: return "kStatus_Timeout";
    case kStatusNoTransferInProgress: return "kStatus_NoTransferInProgress";
    case kStatusFlashSizeError: return "kStatus_FlashSizeError";
    case kStatusFlashAlignmentError: return "kStatus_FlashAlignmentError";
    case kStatusFlashAddressError: return "kStatus_FlashAddressError";
    case kStatusFlashAccessError: return "kStatus_FlashAccessError";
    case kStatusFlashProtectionViolation: return "kStatus_FlashProtectionViolation";
    case kStatusFlashCommandFailure: return "kStatus_FlashCommandFailure";
    case kStatusFlashUnknownProperty: return "kStatus_FlashUnknownProperty";
    case kStatusFlashEraseKeyError: return "kStatus_FlashEraseKeyError";
    case kStatusFlashRegionExecuteOnly: return "kStatus_FlashRegionExecuteOnly";
    case kStatusUnknownCommand: return "kStatus_UnknownCommand";
    case kStatusSecurityViolation: return "kStatus_SecurityViolation";
    case kStatusAbortDataPhase: return "kStatus_AbortDataPhase";
    case kStatusPingError: return "kStatus_Ping";
    case kStatusNoResponse: return "kStatus_NoResponse";
    case kStatusNoResponseExpected: return "kStatus_NoResponseExpected";
    case kStatusUnsupportedCommand: return "kStatus_UnsupportedCommand";
    case kStatusMemoryRangeInvalid: return "kStatusMemoryRangeInvalid";
    case kStatusMemoryReadFailed: return "kStatusMemoryReadFailed";
    case kStatusMemoryWriteFailed: return "kStatusMemoryWriteFailed";
    case kStatusMemoryCumulativeWrite: return "kStatusMemoryCumulativeWrite";
    case kStatusUnknownProperty: return "kStatus_UnknownProperty";
    case kStatusReadOnlyProperty: return "kStatus_ReadOnlyProperty";
    case kStatusInvalidPropertyValue: return "kStatus_InvalidPropertyValue";
    case kStatusAppCrcCheckPassed: return "kStatus_AppCrcCheckPassed";
    case kStatusAppCrcCheckFailed: return "kStatus_AppCrcCheckFailed";
    case kStatusAppCrcCheckInactive: return "kStatus_AppCrcCheckInactive";
    case kStatusAppCrcCheckInvalid: return "kStatus_AppCrcCheckInvalid";
    case kStatusAppCrcCheckOutOfRange: return "kStatus_AppCrcCheckOutOfRange";
    case kStatusNoPingResponse: return "kStatus_NoPingResponse";
    case kStatusInvalidPacketType: return "kStatus_InvalidPacketType";
    case kStatusInvalidCrc: return "kStatus_InvalidCRC";
    case kStatusNoCommandResponse: return "kStatus_NoCommandResponse";
    default: return "";
    }
}

QString KbootStatus::message(uint32_t s)
{
    QString meaning;
    switch (s) {
    case kStatusSuccess: meaning = tr("success"); break;
    case kStatusFail: meaning = tr("the operation failed"); break;
    case kStatusReadOnly: meaning = tr("the target is read-only"); break;
    case kStatusOutOfRange: meaning = tr("a value is out of range"); break;
    case kStatusInvalidArgument: meaning = tr("an argument is invalid"); break;
    case kStatusTimeout: meaning = tr("the bootloader timed out"); break;
    case kStatusNoTransferInProgress: meaning = tr("no transfer is in progress"); break;
    case kStatusFlashSizeError: meaning = tr("the length is not a multiple of the flash unit"); break;
    case kStatusFlashAlignmentError: meaning = tr("the address or length is not aligned to a flash sector"); break;
    case kStatusFlashAddressError: meaning = tr("the address is outside the flash"); break;
    case kStatusFlashAccessError: meaning = tr("flash access error"); break;
    case kStatusFlashProtectionViolation: meaning = tr("the region is protected (e.g. the bootloader)"); break;
    case kStatusFlashCommandFailure: meaning = tr("the flash command failed"); break;
    case kStatusFlashUnknownProperty: meaning = tr("unknown flash property"); break;
    case kStatusFlashEraseKeyError: meaning = tr("wrong erase key"); break;
    case kStatusFlashRegionExecuteOnly: meaning = tr("the region is execute-only"); break;
    case kStatusUnknownCommand: meaning = tr("the bootloader does not know this command"); break;
    case kStatusSecurityViolation: meaning = tr("the command is refused while the chip is secured"); break;
    case kStatusAbortDataPhase: meaning = tr("the data phase was aborted"); break;
    case kStatusPingError: meaning = tr("ping error"); break;
    case kStatusNoResponse: meaning = tr("no response"); break;
    case kStatusNoResponseExpected: meaning = tr("no response expected"); break;
    case kStatusUnsupportedCommand: meaning = tr("the bootloader does not support this command"); break;
    case kStatusMemoryRangeInvalid: meaning = tr("the address range is invalid for this memory"); break;
    case kStatusMemoryReadFailed: meaning = tr("reading the memory failed"); break;
    case kStatusMemoryWriteFailed: meaning = tr("writing the memory failed"); break;
    case kStatusMemoryCumulativeWrite: meaning = tr("the flash was not erased before writing"); break;
    case kStatusUnknownProperty: meaning = tr("the bootloader does not know this property"); break;
    case kStatusReadOnlyProperty: meaning = tr("the property is read-only"); break;
    case kStatusInvalidPropertyValue: meaning = tr("invalid property value"); break;
    case kStatusAppCrcCheckPassed: meaning = tr("application CRC check passed"); break;
    case kStatusAppCrcCheckFailed: meaning = tr("application CRC check failed"); break;
    case kStatusAppCrcCheckInactive: meaning = tr("application CRC check inactive"); break;
    case kStatusAppCrcCheckInvalid: meaning = tr("application CRC check invalid"); break;
    case kStatusAppCrcCheckOutOfRange: meaning = tr("application CRC check range out of range"); break;
    case kStatusNoPingResponse: meaning = tr("no ping response"); break;
    case kStatusInvalidPacketType: meaning = tr("invalid packet type"); break;
    case kStatusInvalidCrc: meaning = tr("packet CRC error"); break;
    case kStatusNoCommandResponse: meaning = tr("no command response"); break;
    default: return tr("unknown status %1").arg(s);
    }
    return tr("%1 (%2): %3").arg(QLatin1String(name(s))).arg(s).arg(meaning);
}

} // namespace imudesk::protocol::kboot
