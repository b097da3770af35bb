#pragma once

#include "absl/status/status.h"
#include "absl/strings/string_view.h"

namespace getme::redis {

// A Redis error reply as a status. Scripts report their outcome this way: an error whose text
// starts with an absl code name and a space or colon (`RESOURCE_EXHAUSTED the queue is full`,
// `NOT_FOUND: job 12`, from Lua's redis.error_reply or error()) becomes that code with the rest
// as the message, after removing what Redis 7 adds to script errors (the `ERR user_script:1: `
// prefix of error("...") and the ` script: <sha1>, on @user_script:1.` suffix). Any other error
// (WRONGTYPE, ERR syntax, a failed redis.call) is INTERNAL "redis: <text>": the store's own code
// is wrong, not the caller's request.
absl::Status StatusFromErrorReply(absl::string_view text);

// A failed exchange on a connection (hiredis's err/errstr and the errno just after the call).
// A socket timeout is DEADLINE_EXCEEDED; everything else (refused, reset, closed, keepalive
// expired, protocol) is UNAVAILABLE. Either way the connection is unusable: a late reply would
// answer the next command. `what` says which command on which server, e.g. "GET on
// redis://host:6379/0".
absl::Status StatusFromConnectionError(int hiredis_error, int error_number,
                                       absl::string_view errstr, absl::string_view what);

}  // namespace getme::redis
