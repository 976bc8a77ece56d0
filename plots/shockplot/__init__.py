"""shockgas's pictures: the run's (pictures.py, one module per picture), the
animation's frames (animation_data.py), the reading of every run file
(run_files.py) and the writing of every picture (saving.py). Importing the
package imports nothing else: a script takes the modules it needs."""
