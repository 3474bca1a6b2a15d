#!/bin/bash
# boxify.sh IN.toml OUT.toml MLO MHI FLO FHI : the same scenario with the uncertainty box's mass and friction ranges replaced
sed -e "/^\[uncertainty.mass\]/,/^range/ s/^range = .*/range = [$3, $4]   # [kg]/" -e "/^\[uncertainty.friction\]/,/^range/ s/^range = .*/range = [$5, $6]/" "$1" > "$2"
