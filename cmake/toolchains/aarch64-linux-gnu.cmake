# SPDX-License-Identifier: MIT
# Cross-building for 64-bit ARM Linux with Debian's cross compiler, tests run under
# qemu-user: how CI checks the NEON contact kernels (packages g++-aarch64-linux-gnu and
# qemu-user).
set(CMAKE_SYSTEM_NAME Linux)
set(CMAKE_SYSTEM_PROCESSOR aarch64)
set(CMAKE_C_COMPILER aarch64-linux-gnu-gcc)
set(CMAKE_CXX_COMPILER aarch64-linux-gnu-g++)
set(CMAKE_CROSSCOMPILING_EMULATOR qemu-aarch64;-L;/usr/aarch64-linux-gnu)
