# Checkpoint and resume through the command in a child process (label `unit`):
# a run killed with SIGKILL after its first checkpoint, and one stopped by
# SIGTERM (which writes a checkpoint and exits with 143), each resumed and
# compared with the uninterrupted run bit for bit (tools/compare_runs.cpp); a
# sweep killed and resumed the same way; an ensemble whose realization 0 keeps
# its states in a state file (shockgas/app/records/state_file.hpp) stopped by SIGTERM; and a
# shard (realizations 1:5) stopped by either signal, resumed, and compared with
# the same shard run uninterrupted.
# One realization stopped inside its run the same ways (single.toml: its first
# checkpoint is its first saved state) continues from its state; also when its
# snapshots go to a states file (single_apart.toml).
# The checkpoint file's refusals are tested in app/test_checkpoint.cpp.
set(checkpoint_dir ${CMAKE_CURRENT_SOURCE_DIR}/checkpoint)
foreach(signal KILL TERM)
  add_test(NAME checkpoint.resumed_after_${signal}
           COMMAND sh ${checkpoint_dir}/stopped_then_resumed.sh $<TARGET_FILE:shockgas> $<TARGET_FILE:compare_runs>
                   ${checkpoint_dir}/ensemble.toml ${PROJECT_BINARY_DIR}/checkpoint-tests/${signal} ${signal})
  add_test(NAME checkpoint.shard_resumed_after_${signal}
           COMMAND sh ${checkpoint_dir}/stopped_then_resumed.sh $<TARGET_FILE:shockgas> $<TARGET_FILE:compare_runs>
                   ${checkpoint_dir}/ensemble.toml ${PROJECT_BINARY_DIR}/checkpoint-tests/shard-${signal} ${signal}
                   --realizations 1:5)
  set_tests_properties(checkpoint.resumed_after_${signal} checkpoint.shard_resumed_after_${signal}
                       PROPERTIES LABELS unit TIMEOUT 300)
endforeach()
add_test(NAME checkpoint.states_apart_resumed_after_TERM
         COMMAND sh ${checkpoint_dir}/stopped_then_resumed.sh $<TARGET_FILE:shockgas> $<TARGET_FILE:compare_runs>
                 ${checkpoint_dir}/states_apart.toml ${PROJECT_BINARY_DIR}/checkpoint-tests/states-apart TERM)
set_tests_properties(checkpoint.states_apart_resumed_after_TERM PROPERTIES LABELS unit TIMEOUT 300)
add_test(NAME checkpoint.sweep_resumed_after_KILL
         COMMAND sh ${checkpoint_dir}/stopped_then_resumed.sh $<TARGET_FILE:shockgas> $<TARGET_FILE:compare_runs>
                 ${checkpoint_dir}/sweep.toml ${PROJECT_BINARY_DIR}/checkpoint-tests/sweep KILL)
set_tests_properties(checkpoint.sweep_resumed_after_KILL PROPERTIES LABELS unit TIMEOUT 300)
foreach(signal KILL TERM)
  add_test(NAME checkpoint.single_apart_resumed_after_${signal}
           COMMAND sh ${checkpoint_dir}/stopped_then_resumed.sh $<TARGET_FILE:shockgas> $<TARGET_FILE:compare_runs>
                   ${checkpoint_dir}/single_apart.toml ${PROJECT_BINARY_DIR}/checkpoint-tests/single-apart-${signal}
                   ${signal})
  set_tests_properties(checkpoint.single_apart_resumed_after_${signal}
                       PROPERTIES LABELS unit TIMEOUT 300
                       ENVIRONMENT "SAID=1 continues from a saved state;SAID_STOPPED=realization 0 saved at t =")
  add_test(NAME checkpoint.single_resumed_after_${signal}
           COMMAND sh ${checkpoint_dir}/stopped_then_resumed.sh $<TARGET_FILE:shockgas> $<TARGET_FILE:compare_runs>
                   ${checkpoint_dir}/single.toml ${PROJECT_BINARY_DIR}/checkpoint-tests/single-${signal} ${signal})
  set_tests_properties(checkpoint.single_resumed_after_${signal}
                       PROPERTIES LABELS unit TIMEOUT 300
                       ENVIRONMENT "SAID=1 continues from a saved state;SAID_STOPPED=realization 0 saved at t =")
endforeach()
