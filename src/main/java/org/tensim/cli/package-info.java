/**
 * The command-line options several commands share, each declared once with its one description and check
 * (picocli mixins): the output folder ({@link org.tensim.cli.OutFolderOption}), the threads of a step
 * ({@link org.tensim.cli.ThreadsOption}), the integrator ({@link org.tensim.cli.IntegratorOption}) and the
 * time step ({@link org.tensim.cli.TimeStepOption}); a command whose default differs passes it to the
 * mixin's constructor. A refused value is a usage error naming the option, the value and what was expected
 * ({@link org.tensim.cli.OptionChecks}). It sits beside the view, below the benchmarks and the application
 * that use it.
 */
package org.tensim.cli;
