"""hwinterp_host: host software for a board running hwinterp's motion_soc
(docs/host.md): the link (Etherbone over UDP or a UART, the sequence guard),
the register map generated from the SystemRDL description, and the
`hwinterp-host` command that streams part programs planned by `hwinterp`."""
__version__ = "0.1.0"
