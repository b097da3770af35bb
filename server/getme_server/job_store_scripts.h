#pragma once

#include "redis/redis_script.h"

namespace getme::server::store_scripts {

// The shared job store's state changes, each one Lua script so that every replica sees it whole
// (Redis runs a script atomically). docs/replicas.md describes the keys; every script takes the
// key prefix as ARGV[1] and builds the keys from it, so the store needs one Redis (not a Redis
// Cluster, whose scripts must declare their keys). Job states are v1::JobState's numbers; "r"
// (requeuing) is the store's own: a lost job whose restart event is being written. Only Submit
// and Append grow the store; the others run even when Redis is over its maxmemory.

// ARGV: prefix, id, owner, describe, header, upload_bytes, max_queued_jobs, max_queued_bytes,
// created_ms. Returns {0} queued, {1, queued jobs} queue full, {2, held bytes} bytes full,
// {3} id taken. The upload list (job:ID:upload) was written before, with a safety expiry.
const redis::RedisScript& Submit();
// ARGV: prefix, replica, lease_ms. The next queued job, now RUNNING here under a lease:
// {id, owner, header, upload_bytes, attempt, seq, created_ms, cancel} or nil.
const redis::RedisScript& Take();
// ARGV: prefix, id, replica, lease_ms. Extends the lease: the cancel reason ("" for none), or nil
// when the job is no longer this replica's (its lease expired and it was requeued).
const redis::RedisScript& Renew();
// ARGV: prefix, id, replica, describe, last_sequence, event... Appends progress events and the
// job's description if the job is still this replica's (1), else nothing (0).
const redis::RedisScript& Append();
// ARGV: prefix, id, replica, state, describe, summary, result_key, final_event, ttl_ms,
// last_sequence. Ends the job if it is still this replica's (1, else 0): state, description,
// summary and result key, the final event, the held bytes released, expiries set.
const redis::RedisScript& Finish();
// ARGV: prefix, limit. Jobs whose lease expired: each becomes "r" with its attempt and sequence
// advanced (the restart event's number) and a short lease of its own, {id, seq, attempt} each.
const redis::RedisScript& ClaimExpired();
// ARGV: prefix, id. A claimed job back at the head of the queue (1), if still "r".
const redis::RedisScript& Requeue();
// ARGV: prefix, id, expected_seq, describe, final_event, ttl_ms. A QUEUED job whose sequence is
// still expected_seq becomes CANCELLED (1); 0 otherwise (the caller looks again).
const redis::RedisScript& CancelQueued();
// ARGV: prefix, id, reason. A RUNNING (or requeuing) job is asked to stop: the replica running it
// reads the reason when it renews its lease. The first reason stays. 1 if asked, 0 otherwise.
const redis::RedisScript& RequestCancel();
// ARGV: prefix, id, taken_key. Moves the job's result list to taken_key (1), or 0 when there is
// none (fetched or expired).
const redis::RedisScript& TakeResult();

}  // namespace getme::server::store_scripts
