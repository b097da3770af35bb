"""The wire contract getme.v1 (proto/getme/v1/*.proto).

The modules in this package (mesh_pb2, params_pb2, quality_pb2, smoother_pb2 and their _pb2_grpc
companions) are generated from the repository's protos by protoc and grpc_python_plugin at build
time (CMake: build/python; pip: setup.py's build_py step). They are never edited or committed:
the proto package is getme.v1, so their own imports ("from getme.v1 import mesh_pb2") resolve to
this package.
"""
