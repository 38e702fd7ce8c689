#include "request_outcome.h"

namespace imudesk::model {

const char *outcomeName(RequestOutcome outcome)
{
    switch (outcome) {
    case RequestOutcome::Pending: return "pending";
    case RequestOutcome::Ok: return "ok";
    case RequestOutcome::Refused: return "refused";
    case RequestOutcome::Invalid: return "invalid";
    case RequestOutcome::Timeout: return "timeout";
    case RequestOutcome::NotSent: return "not sent";
    case RequestOutcome::Cancelled: return "cancelled";
    }
    return "?";
}

} // namespace imudesk::model
