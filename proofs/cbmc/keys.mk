# SPDX-License-Identifier: Apache-2.0
# What a proof's two record keys digest, for proofs/cbmc/run.py, which computes both keys in
# one process instead of one `make result-key` and one `make cover-key` per proof (each of
# which preprocesses every source again and starts keytext.py): read after the proof folder's
# Makefile (make -f Makefile -f keys.mk key-inputs), never included by Makefile.common, so it
# is in no key itself. The recipes of result-key and cover-key in Makefile.common define the
# keys; run.py builds the same text from these values, and a test checks that both give the
# same digests (tools/acsl2cbmc/tests: RecordKeys.test_run_py_keys).
.PHONY: key-inputs
key-inputs: $(GEN_FILES) | $(GEN)/.stamp
	@: $(info property_line	$(PROPERTY_LINE)) $(info cover_line	$(COVER_LINE)) \
	   $(info cover_defines	$(COVER_DEFINES)) $(info defines	$(DEFINES)) \
	   $(info includes	$(INCLUDES)) $(info srcs	$(SRCS)) $(info goto_cc	$(GOTO_CC)) \
	   $(info root	$(ROOT)) $(info makefile_common	$(CBMC_DIR)/Makefile.common)
