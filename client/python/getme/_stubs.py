"""The generated getme.v1 modules, or an ImportError that says how to generate them."""

try:
    from getme.v1 import params_pb2, quality_pb2, smoother_pb2, smoother_pb2_grpc
except ModuleNotFoundError as error:
    # Only a missing generated module is ours to explain; a missing grpc or protobuf is not.
    if not (error.name or "").startswith("getme.v1."):
        raise
    raise ImportError(
        f"getme's generated module {error.name} is missing: use the package from a CMake build "
        "(PYTHONPATH=build/python) or install it with pip (pip install ./client/python), which "
        "generate getme/v1/*_pb2.py from proto/getme/v1") from error

__all__ = ["params_pb2", "quality_pb2", "smoother_pb2", "smoother_pb2_grpc"]
