# SPDX-License-Identifier: Apache-2.0
# bench/bench.mk: `make bench` (included by the top Makefile; paths are relative
# to the repository root). See bench/README.md.
#
#   make bench            toolchain check, build, run everything, print one table,
#                         write $(BUILD)/bench/results.json (exit 0 unless the
#                         harness itself breaks; targets are reported, not enforced)
#   make bench-check      the exact target lines only (instruction counts and sizes, P1 P2
#                         P5-P9 of bench/README.md): exit 1 when one is missed
#   make bench-build      build the bench programs only
#
# Environment: BENCH_ITEMS (throughput items per variant and round, default 1e8),
# BENCH_ROUNDS (wall-clock rounds, default 21), BENCH_RTT (round trips per round,
# default 1e5), BENCH_BUDGET_S / BENCH_RTT_BUDGET_S (time guards of the throughput and
# round-trip phases, default 180 s / 60 s), BENCH_AP_DIV (the ArduPilot-style ring moves
# items / BENCH_AP_DIV, default 10).

BUILD     ?= build
BENCH_OUT := $(BUILD)/bench
BENCH_OPT := -O2 -g
# the word ring's compile-time capacity, the same as every peer's (bench_ring.cpp checks it)
BENCH_INC := -Ikernel/include -Ikernel/port -Ikernel/spec -Ihal_posix -Ibench/src -DMT_CFG_WRING_CAP=4096u
BENCH_CC  := gcc
BENCH_CXX := g++
BENCH_CSTD   := -std=gnu11 -Wall -Wextra
BENCH_CXXSTD := -std=c++17 -Wall -Wextra -Wno-array-bounds -Wno-stringop-overflow -Wno-stringop-overread

BENCH_KSRC := $(wildcard kernel/src/*.c)
BENCH_KHDR := $(wildcard kernel/include/mt/*.h kernel/port/*.h kernel/spec/*.h kernel/src/*.h hal_posix/*.h)
BENCH_HDR  := $(wildcard bench/src/*.h bench/src/*.hpp)

# kernel objects per configuration: def (default config) and t255
# (-DMT_CFG_SCHED_MAX_TASKS=255); same -O2 flags as every peer.
BENCH_CFG_def  :=
BENCH_CFG_t255 := -DMT_CFG_SCHED_MAX_TASKS=255

define bench_kobjs
$(BENCH_OUT)/obj/$(1)/%.o: kernel/src/%.c $(BENCH_KHDR)
	@mkdir -p $$(@D)
	$(BENCH_CC) $(BENCH_CSTD) $(BENCH_OPT) $(BENCH_CFG_$(1)) $(BENCH_INC) -Ikernel/src -c $$< -o $$@
$(BENCH_OUT)/obj/$(1)/bench/%.o: bench/src/%.c $(BENCH_KHDR) $(BENCH_HDR)
	@mkdir -p $$(@D)
	$(BENCH_CC) $(BENCH_CSTD) $(BENCH_OPT) $(BENCH_CFG_$(1)) $(BENCH_INC) -c $$< -o $$@
BENCH_KOBJ_$(1) := $(patsubst kernel/src/%.c,$(BENCH_OUT)/obj/$(1)/%.o,$(BENCH_KSRC))
endef
$(eval $(call bench_kobjs,def))
$(eval $(call bench_kobjs,t255))

$(BENCH_OUT)/obj/def/posix/port.o: hal_posix/port.c $(BENCH_KHDR)
	@mkdir -p $(@D)
	$(BENCH_CC) $(BENCH_CSTD) $(BENCH_OPT) $(BENCH_INC) -c $< -o $@

$(BENCH_OUT)/obj/def/bench/bench_kernel_posix.o: bench/src/bench_kernel.c $(BENCH_KHDR) $(BENCH_HDR)
	@mkdir -p $(@D)
	$(BENCH_CC) $(BENCH_CSTD) $(BENCH_OPT) -DBENCH_POSIX_PORT $(BENCH_INC) -c $< -o $@

BENCH_REF_def  := $(BENCH_OUT)/obj/def/bench/ref_ap_sched.o $(BENCH_OUT)/obj/def/bench/ref_ap_sync.o \
                  $(BENCH_OUT)/obj/def/bench/stub_time.o
BENCH_REF_t255 := $(BENCH_OUT)/obj/t255/bench/ref_ap_sched.o $(BENCH_OUT)/obj/t255/bench/ref_ap_sync.o \
                  $(BENCH_OUT)/obj/t255/bench/stub_time.o

# rings: kernel + hal_posix port + boost + the ArduPilot-style reference
$(BENCH_OUT)/bench_ring: bench/src/bench_ring.cpp $(BENCH_HDR) $(BENCH_KOBJ_def) $(BENCH_OUT)/obj/def/posix/port.o
	$(BENCH_CXX) $(BENCH_CXXSTD) $(BENCH_OPT) $(BENCH_INC) $< $(BENCH_KOBJ_def) \
	    $(BENCH_OUT)/obj/def/posix/port.o -pthread -o $@

# scheduler / procs / semaphores with the bench-only port (stub time)
$(BENCH_OUT)/kernel_stub: $(BENCH_OUT)/obj/def/bench/bench_kernel.o $(BENCH_OUT)/obj/def/bench/port_stub.o \
                          $(BENCH_REF_def) $(BENCH_KOBJ_def)
	$(BENCH_CC) $^ -pthread -o $@
$(BENCH_OUT)/kernel_stub255: $(BENCH_OUT)/obj/t255/bench/bench_kernel.o $(BENCH_OUT)/obj/t255/bench/port_stub.o \
                             $(BENCH_REF_t255) $(BENCH_KOBJ_t255)
	$(BENCH_CC) $^ -pthread -o $@
# ... and with the real host port (semaphores; scheduler in simulated-time mode)
$(BENCH_OUT)/kernel_posix: $(BENCH_OUT)/obj/def/bench/bench_kernel_posix.o $(BENCH_OUT)/obj/def/posix/port.o \
                           $(BENCH_REF_def) $(BENCH_KOBJ_def)
	$(BENCH_CC) $^ -pthread -o $@

BENCH_BINS := $(BENCH_OUT)/bench_ring $(BENCH_OUT)/kernel_stub $(BENCH_OUT)/kernel_stub255 \
              $(BENCH_OUT)/kernel_posix

.PHONY: bench bench-check bench-build
bench-build: $(BENCH_BINS)

bench:
	@tools/bootstrap.sh bench
	@tools/bootstrap.sh cross >/dev/null 2>&1 || \
	    echo "bench: Cortex-M4 toolchain not available; code-size rows will be skipped"
	@$(MAKE) --no-print-directory -j$$(nproc 2>/dev/null || echo 2) BUILD=$(BUILD) bench-build
	@python3 bench/run.py --build $(BUILD)

bench-check:
	@tools/bootstrap.sh bench
	@tools/bootstrap.sh cross
	@$(MAKE) --no-print-directory -j$$(nproc 2>/dev/null || echo 2) BUILD=$(BUILD) bench-build
	@python3 bench/run.py --build $(BUILD) --check
