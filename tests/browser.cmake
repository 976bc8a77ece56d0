# What a lecture room sees, label `browser` (part of the default `ctest -LE slow`):
# the report.html of two gallery runs opened in headless Chromium
# (tests/browser/check_report_html.py), and the cooling scene's animation
# (tests/browser/check_animation.py: frames, size, the file plays), and `shockgas
# animate --fps --size --frames` on the sine scene. They need
# Debian's /usr/bin/python3 with its packages, and Chromium or ffmpeg; where
# one is missing the test is skipped with a message (exit 77).
set(browser_out ${PROJECT_BINARY_DIR}/browser-tests)
set(gallery ${PROJECT_SOURCE_DIR}/data/scenes/gallery)
set(checks ${CMAKE_CURRENT_SOURCE_DIR}/browser)
set(python "[ -x /usr/bin/python3 ] || { echo 'skipped: no /usr/bin/python3 (scripts/setup)'; exit 77; }")

# Two runs with their plots and a short animation (12 frames), then their pages:
# the sine (particles and continuum) and the Riemann problems (continuum only),
# each a test of its own (a run, its plots and a browser: about 10 CPU-seconds).
foreach(scene sine riemann)
  add_test(NAME browser.report_html_${scene}
           COMMAND sh -c "${python}; rm -rf '${browser_out}/report/${scene}' && \
'$<TARGET_FILE:shockgas>' run '${gallery}/${scene}.toml' --set output.animation_frames=12 --out '${browser_out}/report/${scene}' -q && \
/usr/bin/python3 '${checks}/check_report_html.py' '${browser_out}/report/${scene}'")
endforeach()

# The cooling scene as it stands, its frames recorded by the run and drawn by `shockgas animate`.
add_test(NAME browser.cooling_animation
         COMMAND sh -c "${python}; rm -rf '${browser_out}/cooling' && \
'$<TARGET_FILE:shockgas>' run '${gallery}/cooling.toml' --no-plots --out '${browser_out}/cooling' -q && \
'$<TARGET_FILE:shockgas>' animate '${browser_out}/cooling' && \
/usr/bin/python3 '${checks}/check_animation.py' '${browser_out}/cooling'")

# `shockgas animate` asked for another size, fewer frames and a frame rate: the files follow.
add_test(NAME browser.animate_options
         COMMAND sh -c "${python}; rm -rf '${browser_out}/options' && \
'$<TARGET_FILE:shockgas>' run '${gallery}/sine.toml' --set output.animation_frames=12 --no-plots --out '${browser_out}/options' -q && \
'$<TARGET_FILE:shockgas>' animate '${browser_out}/options' --fps 5 --size 640x360 --frames 7 && \
/usr/bin/python3 '${checks}/check_animation.py' '${browser_out}/options' --size 640x360 --frames 7 --fps 5")

set_tests_properties(browser.report_html_sine browser.report_html_riemann browser.cooling_animation
                     browser.animate_options PROPERTIES LABELS browser SKIP_RETURN_CODE 77
                     TIMEOUT 300 WORKING_DIRECTORY ${PROJECT_SOURCE_DIR})
