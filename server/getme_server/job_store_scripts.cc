#include "getme_server/job_store_scripts.h"

#include <string>

#include "absl/strings/str_cat.h"

namespace getme::server::store_scripts {
namespace {

// Shared by every script: Redis's own clock (so replicas with skewed clocks agree on when a lease
// ends), and the end of a job.
constexpr char kPrelude[] = R"lua(
local function now_ms()
  local t = redis.call('TIME')
  return tonumber(t[1]) * 1000 + math.floor(tonumber(t[2]) / 1000)
end
-- What every end of a job does once its record holds the final state: the final event, the lease,
-- upload and held bytes released, the record and events kept twice the result's time to live.
local function end_job(p, id, upload_bytes, final_event, ttl_ms)
  local job = p .. 'job:' .. id
  redis.call('XADD', job .. ':events', '*', 'e', final_event)
  redis.call('ZREM', p .. 'running', id)
  redis.call('DECRBY', p .. 'held_bytes', tonumber(upload_bytes))
  redis.call('DEL', job .. ':upload')
  local keep = 2 * tonumber(ttl_ms)
  redis.call('PEXPIRE', job, keep)
  redis.call('PEXPIRE', job .. ':events', keep)
end
)lua";

redis::RedisScript Script(const char* body) {
  return redis::RedisScript(absl::StrCat(kPrelude, body));
}

// A script that ends, moves or renews jobs and writes only a few bytes (most free an upload):
// it still runs when Redis is over its maxmemory, so a full store can end its jobs as failed and
// keep its leases instead of restarting them (Redis 7's script flags).
redis::RedisScript SmallWriteScript(const char* body) {
  return redis::RedisScript(absl::StrCat("#!lua flags=allow-oom\n", kPrelude, body));
}

}  // namespace

const redis::RedisScript& Submit() {
  static const redis::RedisScript script = Script(R"lua(
local p, id, owner = ARGV[1], ARGV[2], ARGV[3]
local job = p .. 'job:' .. id
if redis.call('EXISTS', job) == 1 then return {3} end
local queued = redis.call('LLEN', p .. 'queue')
if queued >= tonumber(ARGV[7]) then
  redis.call('DEL', job .. ':upload')
  return {1, queued}
end
local held = tonumber(redis.call('GET', p .. 'held_bytes') or '0')
local bytes = tonumber(ARGV[6])
if held + bytes > tonumber(ARGV[8]) then
  redis.call('DEL', job .. ':upload')
  return {2, held}
end
redis.call('HSET', job, 'owner', owner, 'state', '1', 'describe', ARGV[4], 'header', ARGV[5],
           'upload_bytes', ARGV[6], 'attempt', '1', 'seq', '0', 'created_ms', ARGV[9],
           'fetcher', ARGV[10])
redis.call('PERSIST', job .. ':upload')
redis.call('RPUSH', p .. 'queue', id)
redis.call('INCRBY', p .. 'held_bytes', bytes)
redis.call('ZADD', p .. 'jobs', ARGV[9], id)
redis.call('ZADD', p .. 'owner:' .. owner, ARGV[9], id)
redis.call('RPUSH', p .. 'doorbell', '1')
redis.call('LTRIM', p .. 'doorbell', 0, 1023)
return {0}
)lua");
  return script;
}

const redis::RedisScript& Take() {
  static const redis::RedisScript script = SmallWriteScript(R"lua(
local p, replica, lease = ARGV[1], ARGV[2], tonumber(ARGV[3])
while true do
  local id = redis.call('LPOP', p .. 'queue')
  if not id then return false end
  local job = p .. 'job:' .. id
  if redis.call('HGET', job, 'state') == '1' then
    redis.call('HSET', job, 'state', '2', 'replica', replica)
    redis.call('ZADD', p .. 'running', now_ms() + lease, id)
    local f = redis.call('HMGET', job, 'owner', 'header', 'upload_bytes', 'attempt', 'seq',
                         'created_ms', 'cancel', 'fetcher')
    return {id, f[1], f[2], f[3], f[4], f[5], f[6], f[7] or '', f[8] or '0'}
  end
end
)lua");
  return script;
}

const redis::RedisScript& Renew() {
  static const redis::RedisScript script = SmallWriteScript(R"lua(
local p, id, replica = ARGV[1], ARGV[2], ARGV[3]
local job = p .. 'job:' .. id
local f = redis.call('HMGET', job, 'state', 'replica', 'cancel')
if f[1] ~= '2' or f[2] ~= replica then return false end
redis.call('ZADD', p .. 'running', 'XX', now_ms() + tonumber(ARGV[4]), id)
return f[3] or ''
)lua");
  return script;
}

const redis::RedisScript& Append() {
  static const redis::RedisScript script = Script(R"lua(
local p, id, replica = ARGV[1], ARGV[2], ARGV[3]
local job = p .. 'job:' .. id
local f = redis.call('HMGET', job, 'state', 'replica')
if f[1] ~= '2' or f[2] ~= replica then return 0 end
for i = 6, #ARGV do redis.call('XADD', job .. ':events', '*', 'e', ARGV[i]) end
redis.call('HSET', job, 'describe', ARGV[4], 'seq', ARGV[5])
return 1
)lua");
  return script;
}

const redis::RedisScript& Finish() {
  static const redis::RedisScript script = SmallWriteScript(R"lua(
local p, id, replica = ARGV[1], ARGV[2], ARGV[3]
local job = p .. 'job:' .. id
local f = redis.call('HMGET', job, 'state', 'replica', 'upload_bytes')
if f[1] ~= '2' or f[2] ~= replica then return 0 end
redis.call('HSET', job, 'state', ARGV[4], 'describe', ARGV[5], 'summary', ARGV[6],
           'result_key', ARGV[7], 'seq', ARGV[10], 'finished_ms', now_ms())
end_job(p, id, f[3], ARGV[8], ARGV[9])
return 1
)lua");
  return script;
}

const redis::RedisScript& ClaimExpired() {
  static const redis::RedisScript script = SmallWriteScript(R"lua(
local p = ARGV[1]
local now = now_ms()
local ids = redis.call('ZRANGEBYSCORE', p .. 'running', '-inf', now, 'LIMIT', 0,
                       tonumber(ARGV[2]))
local claimed = {}
for _, id in ipairs(ids) do
  local job = p .. 'job:' .. id
  local state = redis.call('HGET', job, 'state')
  if state == '2' then
    local seq = redis.call('HINCRBY', job, 'seq', 1)
    local attempt = redis.call('HINCRBY', job, 'attempt', 1)
    redis.call('HSET', job, 'state', 'r', 'replica', '')
    -- A short lease of its own: a reaper that dies before Requeue leaves it to the next one.
    redis.call('ZADD', p .. 'running', now + 5000, id)
    table.insert(claimed, {id, seq, attempt})
  elseif state == 'r' then
    redis.call('ZADD', p .. 'running', now + 5000, id)
    local f = redis.call('HMGET', job, 'seq', 'attempt')
    table.insert(claimed, {id, tonumber(f[1]), tonumber(f[2])})
  else
    redis.call('ZREM', p .. 'running', id)
  end
end
return claimed
)lua");
  return script;
}

const redis::RedisScript& Requeue() {
  static const redis::RedisScript script = SmallWriteScript(R"lua(
local p, id = ARGV[1], ARGV[2]
local job = p .. 'job:' .. id
if redis.call('HGET', job, 'state') ~= 'r' then return 0 end
redis.call('HSET', job, 'state', '1')
redis.call('ZREM', p .. 'running', id)
redis.call('LPUSH', p .. 'queue', id)
redis.call('RPUSH', p .. 'doorbell', '1')
redis.call('LTRIM', p .. 'doorbell', 0, 1023)
return 1
)lua");
  return script;
}

const redis::RedisScript& CancelQueued() {
  static const redis::RedisScript script = SmallWriteScript(R"lua(
local p, id = ARGV[1], ARGV[2]
local job = p .. 'job:' .. id
local f = redis.call('HMGET', job, 'state', 'seq', 'upload_bytes')
if f[1] ~= '1' or f[2] ~= ARGV[3] then return 0 end
redis.call('LREM', p .. 'queue', 0, id)
redis.call('HSET', job, 'state', '5', 'describe', ARGV[4], 'seq', tonumber(ARGV[3]) + 1,
           'finished_ms', now_ms())
end_job(p, id, f[3], ARGV[5], ARGV[6])
return 1
)lua");
  return script;
}

const redis::RedisScript& RequestCancel() {
  static const redis::RedisScript script = SmallWriteScript(R"lua(
local p, id = ARGV[1], ARGV[2]
local job = p .. 'job:' .. id
local state = redis.call('HGET', job, 'state')
if state ~= '2' and state ~= 'r' then return 0 end
redis.call('HSETNX', job, 'cancel', ARGV[3])
return 1
)lua");
  return script;
}

const redis::RedisScript& TakeResult() {
  static const redis::RedisScript script = SmallWriteScript(R"lua(
local p, id = ARGV[1], ARGV[2]
local key = redis.call('HGET', p .. 'job:' .. id, 'result_key')
if not key or key == '' or redis.call('EXISTS', key) == 0 then return 0 end
redis.call('RENAME', key, ARGV[3])
return 1
)lua");
  return script;
}

}  // namespace getme::server::store_scripts
