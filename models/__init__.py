"""Scenarios bundled with critmoment (installed as ``critmoment.models``)."""
