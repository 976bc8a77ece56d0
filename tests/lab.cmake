# The lab (lab/, docs/gallery.md, "The lab"): its engine against the library (tests/lab/*.cpp,
# label `unit`); its WebAssembly build against the native one, bit for bit, under
# Node (lab.wasm_matches_native, label `unit`); and its page, written by
# `shockgas lab`, in headless Chromium (lab.page, label `browser`). Where
# emscripten is missing (cmake/Lab.cmake says so at configure time), the last
# two are skipped with that message (exit 77).
shockgas_test_folder(lab shockgas_lab_engine shockgas_app)

set(lab_cases ${CMAKE_CURRENT_SOURCE_DIR}/lab/cases.txt)
set(lab_out ${PROJECT_BINARY_DIR}/lab-tests)
if(SHOCKGAS_LAB_MISSING)
  set(lab_skip "echo 'skipped: the lab was not built: ${SHOCKGAS_LAB_MISSING}'; exit 77")
else()
  set(lab_skip "true")
endif()

# Both digests of every case, compared byte for byte; the counts say the cases ran
# (11 runs to their end, 3 refused in the library's words), so an empty or
# truncated pair of outputs cannot pass.
add_test(NAME lab.wasm_matches_native
         COMMAND sh -c "${lab_skip}; mkdir -p '${lab_out}' && \
'$<TARGET_FILE:lab_check>' '${lab_cases}' > '${lab_out}/native.txt' && \
NODE_PATH=/usr/share/nodejs '${SHOCKGAS_NODE}' '${CMAKE_CURRENT_SOURCE_DIR}/lab/check_wasm.js' \
'${PROJECT_BINARY_DIR}/lab-engine' '${lab_cases}' > '${lab_out}/wasm.txt' && \
test \"$(grep -c '^steps .* code 0$' '${lab_out}/native.txt')\" = 11 && \
test \"$(grep -c '^error ' '${lab_out}/native.txt')\" = 3 && \
diff '${lab_out}/native.txt' '${lab_out}/wasm.txt' && echo 'the WebAssembly build computed the same bits'")

# lab.page checks what the page does; lab.page_frame_rate (label slow) checks the
# same and measures the frame rate besides (4 s at each of two sizes, with the
# runs' start: about 10 s more), which a default test does not time.
foreach(case page page_frame_rate)
  set(rate_option "")
  if(case STREQUAL "page_frame_rate")
    set(rate_option "--frame-rate")
  endif()
  add_test(NAME lab.${case}
           COMMAND sh -c "${lab_skip}; [ -x /usr/bin/python3 ] || { echo 'skipped: no /usr/bin/python3'; exit 77; }; \
rm -rf '${lab_out}/${case}' && '$<TARGET_FILE:shockgas>' lab --out '${lab_out}/${case}' && \
/usr/bin/python3 '${CMAKE_CURRENT_SOURCE_DIR}/lab/check_lab_page.py' '${lab_out}/${case}' ${rate_option}")
endforeach()

set_tests_properties(lab.wasm_matches_native PROPERTIES LABELS unit SKIP_RETURN_CODE 77 TIMEOUT 300)
set_tests_properties(lab.page PROPERTIES LABELS browser SKIP_RETURN_CODE 77 TIMEOUT 300)
set_tests_properties(lab.page_frame_rate PROPERTIES LABELS "browser;slow" SKIP_RETURN_CODE 77 TIMEOUT 300)
