#!/usr/bin/env python3
"""Checks docker/ without a Docker engine (none runs on the project's machines).

What can be checked here, is:
  * the Dockerfile's build stage runs scripts/setup.sh and scripts/build.sh (the README's way),
    and both stages start from debian:bookworm-slim;
  * every shared library that `ldd` reports for the binaries the runtime stage copies, and every
    library the CLI opens at run time for a file format (a LazyFunctionTable in client/), is provided
    by a Debian package (`dpkg -S` on this machine) that the runtime stage installs, directly or
    as a dependency apt pulls in (`apt-cache depends --recurse`): the format libraries bring
    HDF5, netCDF and their own dependencies, which the Dockerfile need not spell out;
  * the runtime stage runs as a non-root user, exposes the ports the server listens on, and its
    HEALTHCHECK asks /healthz on the HTTP port;
  * compose.yaml and docker/k8s/*.yaml parse, and their ports and probes agree with the
    Dockerfile.
What it cannot check (docker build/run, compose up, kubectl apply) docs/deployment.md lists.

usage: check_container_files.py REPO BINARY... [--sanitizer-build]
"""
import os
import re
import shlex
import subprocess
import sys

import yaml

GRPC_PORT = 50051
HTTP_PORT = 8080
# A sanitizer build links its runtime; the image ships the Release build, which does not.
SANITIZER_PACKAGES = {"libasan8", "libubsan1", "libtsan2", "liblsan0"}

failures = []
passes = []


def check(ok, message):
    print(("ok   " if ok else "FAIL ") + message)
    (passes if ok else failures).append(message)


def dockerfile_stages(path):
    """[(stage name, base image, [(instruction, argument)])], continuation lines joined."""
    with open(path, encoding="utf-8") as f:
        text = re.sub(r"\\\n", " ", f.read())
    stages = []
    for line in text.splitlines():
        line = line.strip()
        if not line or line.startswith("#"):
            continue
        instruction, _, argument = line.partition(" ")
        instruction = instruction.upper()
        if instruction == "FROM":
            words = argument.split()
            name = words[2] if len(words) >= 3 and words[1].upper() == "AS" else ""
            stages.append((name, words[0], []))
        elif stages:
            stages[-1][2].append((instruction, argument.strip()))
    return stages


def apt_packages(instructions):
    """Packages of every `apt-get install` in the stage's RUN instructions."""
    packages = set()
    for instruction, argument in instructions:
        if instruction != "RUN":
            continue
        for command in re.split(r"&&|;", argument):
            words = shlex.split(command)
            if words[:2] == ["apt-get", "install"]:
                packages.update(w for w in words[2:] if not w.startswith("-"))
    return packages


def path_variants(library):
    """The paths dpkg may know a library by (usrmerge: /lib is /usr/lib, and ldd may report a
    symlink)."""
    variants = []
    for path in (library, os.path.realpath(library)):
        variants.append(path)
        if path.startswith("/usr/lib/"):
            variants.append(path[len("/usr"):])
        elif path.startswith("/lib"):
            variants.append("/usr" + path)
    return variants


def owning_packages(libraries):
    """{library: Debian package or None}, with one `dpkg -S` call for all (it is slow to start)."""
    candidates = sorted({v for library in libraries for v in path_variants(library)})
    result = subprocess.run(["dpkg", "-S", *candidates], capture_output=True, text=True)
    by_path = {}
    for line in result.stdout.splitlines():
        packages, _, path = line.rpartition(": ")
        by_path[path.strip()] = packages.split(",")[0].split(":")[0].strip()
    return {library: next((by_path[v] for v in path_variants(library) if v in by_path), None)
            for library in libraries}


def with_dependencies(packages):
    """The packages apt installs for `packages`: them and their Depends / Pre-Depends, recursively
    (recommends are off in the Dockerfile, so they are not followed)."""
    result = subprocess.run(
        ["apt-cache", "depends", "--recurse", "--no-recommends", "--no-suggests",
         "--no-conflicts", "--no-breaks", "--no-replaces", "--no-enhances", *sorted(packages)],
        capture_output=True, text=True, check=True)
    closure = set(packages)
    for line in result.stdout.splitlines():
        if line and not line[0].isspace():
            closure.add(line.strip().strip("<>").split(":")[0])
    return closure


def shared_libraries(binary):
    output = subprocess.run(["ldd", binary], capture_output=True, text=True, check=True).stdout
    libraries = []
    for line in output.splitlines():
        if "not found" in line:
            check(False, f"{os.path.basename(binary)}: {line.strip()}")
        match = re.search(r"=>\s*(/\S+)", line) or re.match(r"\s*(/\S+)", line)
        if match:
            libraries.append(match.group(1))
    return libraries


# `static LazyFunctionTable<CgnsFunctions> table("libcgns.so.3.4", …`
TABLE_SONAME = re.compile(r'LazyFunctionTable<\w+>\s+\w+\(\s*"([^"]+)"')


def runtime_loaded_libraries(repo):
    """The libraries the CLI opens with dlopen when a format needs them
    (client/formats/runtime_library.h), with their own dependencies: `ldd` cannot see them, so
    their sonames are read from the sources and resolved through the loader's cache."""
    sonames = set()
    for root, _, files in os.walk(os.path.join(repo, "client")):
        for name in files:
            if name.endswith(".cc"):
                with open(os.path.join(root, name), encoding="utf-8") as f:
                    sonames.update(re.findall(TABLE_SONAME, f.read()))
    check(len(sonames) >= 2, f"the CLI opens {len(sonames)} format libraries at run time "
                             f"({', '.join(sorted(sonames))})")
    cache = subprocess.run(["/sbin/ldconfig", "-p"], capture_output=True, text=True,
                           check=True).stdout
    libraries = []
    for soname in sorted(sonames):
        match = re.search(rf"^\s*{re.escape(soname)} \(libc6,x86-64\) => (\S+)", cache, re.M)
        check(match, f"{soname} is installed on this machine")
        if match:
            libraries.append(match.group(1))
            libraries.extend(shared_libraries(match.group(1)))
    return libraries


def main(argv):
    sanitizer_build = "--sanitizer-build" in argv
    args = [a for a in argv if a != "--sanitizer-build"]
    repo, binaries = args[0], args[1:]
    stages = dockerfile_stages(os.path.join(repo, "docker", "Dockerfile"))
    check(len(stages) >= 2, "the Dockerfile has a build and a runtime stage")
    build, runtime = stages[0], stages[-1]
    for name, base, _ in stages:
        check(base == "debian:bookworm-slim", f"stage '{name}' starts from debian:bookworm-slim")
    build_runs = " ".join(a for i, a in build[2] if i == "RUN")
    check("bash scripts/setup.sh" in build_runs, "the build stage runs scripts/setup.sh")
    check("bash scripts/build.sh" in build_runs, "the build stage runs scripts/build.sh")

    runtime_instructions = runtime[2]
    packages = apt_packages(runtime_instructions)
    check(packages, f"the runtime stage installs {len(packages)} packages")
    installed = with_dependencies(packages)
    copied = " ".join(a for i, a in runtime_instructions if i == "COPY")
    for binary in binaries:
        name = os.path.basename(binary)
        check(f"/src/build/bin/{name}" in copied, f"the runtime stage copies build/bin/{name}")
        needed = {}
        libraries = shared_libraries(binary)
        if name in ("getme", "getme-remote"):
            libraries += runtime_loaded_libraries(repo)
        for library, package in owning_packages(libraries).items():
            if not (sanitizer_build and package in SANITIZER_PACKAGES):
                needed.setdefault(package, []).append(library)
        for package, libraries in sorted(needed.items(), key=lambda item: str(item[0])):
            if package not in installed:
                check(False, f"{name}: {', '.join(libraries)} come(s) from {package}, which the "
                             "runtime stage does not install, nor any package it installs "
                             "depends on")
        check(all(p in installed for p in needed),
              f"{name}: all {sum(map(len, needed.values()))} shared libraries come from the "
              f"runtime stage's packages or their dependencies "
              f"({', '.join(sorted(map(str, needed)))})")

    users = [a for i, a in runtime_instructions if i == "USER"]
    check(users and users[-1].split(":")[0] not in ("root", "0"), "the runtime stage is not root")
    exposed = {int(p) for i, a in runtime_instructions if i == "EXPOSE" for p in a.split()}
    check(exposed == {GRPC_PORT, HTTP_PORT}, f"EXPOSE {sorted(exposed)}")
    healthcheck = " ".join(a for i, a in runtime_instructions if i == "HEALTHCHECK")
    check("/healthz" in healthcheck and f"/{HTTP_PORT}" in healthcheck,
          "HEALTHCHECK asks /healthz on the HTTP port")
    command = " ".join(a for i, a in runtime_instructions if i in ("CMD", "ENTRYPOINT"))
    check(f"--listen=0.0.0.0:{GRPC_PORT}" in command and
          f"--http_listen=0.0.0.0:{HTTP_PORT}" in command,
          "the server listens on all interfaces on the exposed ports")

    with open(os.path.join(repo, "docker", "compose.yaml"), encoding="utf-8") as f:
        compose = yaml.safe_load(f)
    service = compose["services"]["getme"]
    check(service["build"]["dockerfile"] == "docker/Dockerfile", "compose builds docker/Dockerfile")
    published = {int(str(p).split(":")[-1]) for p in service["ports"]}
    check(published == exposed, f"compose publishes {sorted(published)}")
    check(service.get("restart") in ("always", "unless-stopped", "on-failure"),
          "compose has a restart policy")
    limits = service["deploy"]["resources"]["limits"]
    check("cpus" in limits and "memory" in limits, "compose limits CPU and memory")
    check("/healthz" in " ".join(service["healthcheck"]["test"]), "compose health check: /healthz")
    check(any(f"--http_listen=0.0.0.0:{HTTP_PORT}" in a for a in service["command"]),
          "compose's command keeps the HTTP port")

    documents = []
    k8s = os.path.join(repo, "docker", "k8s")
    for name in sorted(os.listdir(k8s)):
        if name.endswith(".yaml"):
            with open(os.path.join(k8s, name), encoding="utf-8") as f:
                documents.extend(d for d in yaml.safe_load_all(f) if d)
    deployments = [d for d in documents if d["kind"] == "Deployment"]
    # The replicas' job store (redis.yaml) is checked on its own below.
    services = [d for d in documents if d["kind"] == "Service" and
                d["spec"]["selector"].get("app") == "getme"]
    check(len(deployments) == 1 and services, "k8s: a Deployment and Services")
    pod = deployments[0]["spec"]["template"]["spec"]
    container = pod["containers"][0]
    ports = {p["name"]: p["containerPort"] for p in container["ports"]}
    check(ports == {"grpc": GRPC_PORT, "http": HTTP_PORT}, f"k8s container ports {ports}")
    check(container["livenessProbe"]["grpc"]["port"] == GRPC_PORT, "k8s liveness: gRPC health")
    check(container["readinessProbe"]["grpc"]["port"] == GRPC_PORT and
          container["readinessProbe"]["grpc"].get("service") == "getme.v1.Smoother",
          "k8s readiness: gRPC health of getme.v1.Smoother")
    resources = container["resources"]
    check({"cpu", "memory"} <= set(resources["requests"]) and
          {"cpu", "memory"} <= set(resources["limits"]), "k8s requests and limits")
    check(pod["securityContext"]["runAsNonRoot"] is True, "k8s runs as non-root")
    check(any(f"--http_listen=0.0.0.0:{HTTP_PORT}" in a for a in container["args"]),
          "k8s args keep the HTTP port")
    for service in services:
        for port in service["spec"]["ports"]:
            check(port["targetPort"] in ports, f"k8s Service {service['metadata']['name']} "
                  f"targets container port '{port['targetPort']}'")
    check(any(s["spec"].get("clusterIP") == "None" for s in services),
          "k8s: a headless Service for client-side gRPC balancing")

    # Replicas share jobs through Redis (docs/replicas.md): the Deployment points every replica
    # at the StatefulSet's Service, with the password from the Secret both use.
    stores = [d for d in documents if d["kind"] == "StatefulSet"]
    check(len(stores) == 1, "k8s: a Redis StatefulSet")
    redis_container = stores[0]["spec"]["template"]["spec"]["containers"][0]
    redis_ports = {p["name"]: p["containerPort"] for p in redis_container["ports"]}
    redis_services = [d for d in documents if d["kind"] == "Service" and
                      d["spec"]["selector"].get("app") == stores[0]["metadata"]["labels"]["app"]]
    check(len(redis_services) == 1 and
          all(p["targetPort"] in redis_ports for p in redis_services[0]["spec"]["ports"]),
          "k8s: a Service for the Redis StatefulSet")
    store_host = f"{redis_services[0]['metadata']['name']}:{redis_ports['redis']}"
    check(any(a.startswith("--job_store=redis://") and a.endswith(f"@{store_host}")
              for a in container["args"]), f"k8s replicas use --job_store at {store_host}")
    secrets = {d["metadata"]["name"] for d in documents if d["kind"] == "Secret"}
    for env in container.get("env", []) + redis_container.get("env", []):
        ref = env.get("valueFrom", {}).get("secretKeyRef", {})
        check(ref.get("name") in secrets, f"k8s env {env['name']} comes from a Secret here")

    with open(os.path.join(repo, "docker", "compose.replicas.yaml"), encoding="utf-8") as f:
        replicas = yaml.safe_load(f)["services"]
    getmes = [s for name, s in replicas.items() if name.startswith("getme-")]
    check("redis" in replicas and len(getmes) >= 2, "compose.replicas: Redis and two or more replicas")
    check(all("--job_store=redis://redis:6379" in s["command"] for s in getmes),
          "compose.replicas: every replica uses the Redis service as its job store")
    host_ports = [p.split(":")[0] for s in getmes for p in s["ports"]]
    check(len(host_ports) == len(set(host_ports)), "compose.replicas: no host port published twice")

    print(f"docker_files: {len(passes)} passed, {len(failures)} failed")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
