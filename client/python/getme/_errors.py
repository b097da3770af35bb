"""getme.Error: a failed call, with the gRPC status code and the server's message."""

import grpc


class Error(Exception):
    """A call to getme-server failed.

    Attributes:
      code: the grpc.StatusCode, e.g. INVALID_ARGUMENT for a mesh or parameter the server refuses
        (the message names the element, node or field), UNAVAILABLE when the server cannot be
        reached, DEADLINE_EXCEEDED when `timeout` passed, CANCELLED when the call was cancelled.
      details: the server's message, unchanged.
    """

    def __init__(self, code: grpc.StatusCode, details: str):
        super().__init__(f"{code.name}: {details}")
        self.code = code
        self.details = details


def from_rpc_error(error: grpc.RpcError) -> Error:
    """The getme.Error for a grpc.RpcError raised by a call (a grpc.Call carries code/details)."""
    code = error.code() if hasattr(error, "code") else grpc.StatusCode.UNKNOWN
    details = error.details() if hasattr(error, "details") else str(error)
    return Error(code if code is not None else grpc.StatusCode.UNKNOWN, details or "")
