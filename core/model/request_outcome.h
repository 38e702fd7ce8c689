#pragma once
// What became of a request to a device (issue 54, point 4): one shape for a HiPNUC module's
// ASCII reply, a text command's reply and every request the session engine runs, whatever the
// family (HEC495, Modbus, CAN answers too).
namespace imudesk::model {

enum class RequestOutcome {
    Pending,   // not answered yet
    Ok,        // answered, and the answer says it worked
    Refused,   // answered, and the device says it did not (an ERR line, FF, an exception, an abort)
    Invalid,   // answered with something the manual does not allow there
    Timeout,   // no answer after every attempt
    NotSent,   // the link is not open, writing failed, or the arguments were refused
    Cancelled, // the session was closed first
};

// "pending", "ok", "refused", "invalid", "timeout", "not sent", "cancelled".
const char *outcomeName(RequestOutcome outcome);

} // namespace imudesk::model
