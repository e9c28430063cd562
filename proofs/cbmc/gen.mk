# SPDX-License-Identifier: Apache-2.0
# The translator's run, shared by every proof folder (included by Makefile.common): the ACSL
# contracts of kernel/ become build/proof/cbmc/gen/ (<F>_contract.h, mtc_logic.h, mtc_stubs.c,
# manifest.json). Not part of a record key (assumption B10): the files it writes are.
gen: $(GEN)/.stamp
$(GEN)/.stamp: $(wildcard $(ROOT)/tools/acsl2cbmc/*.py) \
        $(wildcard $(ROOT)/kernel/include/mt/*.h $(ROOT)/kernel/port/*.h $(ROOT)/kernel/spec/*.h \
                   $(ROOT)/kernel/src/*.h $(ROOT)/kernel/src/*.c)
	$(PYTHON) $(ROOT)/tools/acsl2cbmc --root $(ROOT) --out $(GEN) --quiet
	@touch $@
