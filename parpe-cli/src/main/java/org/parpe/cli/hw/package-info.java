/**
 * The serial-bus side of the command line: {@code parpe run --port} (driver, safety, hardware
 * and simulator at once), {@code parpe emulate}, {@code parpe record}, and the bus benchmark
 * (internal to the CLI).
 */
package org.parpe.cli.hw;
