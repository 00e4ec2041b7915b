# PostgreSQL for deploy/docker-compose.scale.yml, from Debian 12's own package (PostgreSQL 15):
# a cluster in /var/lib/postgresql/data on first start, a `socsim` role and database, password
# from POSTGRES_PASSWORD, connections from the compose network.
FROM debian:12-slim
RUN apt-get update && apt-get install -y --no-install-recommends postgresql-15 && rm -rf /var/lib/apt/lists/*
USER postgres
ENV PGDATA=/var/lib/postgresql/data PATH=/usr/lib/postgresql/15/bin:$PATH
EXPOSE 5432
VOLUME /var/lib/postgresql/data
CMD set -e; \
    if [ ! -s "$PGDATA/PG_VERSION" ]; then \
      printf '%s\n' "$POSTGRES_PASSWORD" > /tmp/pw; \
      initdb -D "$PGDATA" -U postgres --pwfile=/tmp/pw --auth-host=scram-sha-256 --auth-local=trust; rm /tmp/pw; \
      echo "host all all 0.0.0.0/0 scram-sha-256" >> "$PGDATA/pg_hba.conf"; \
      pg_ctl -D "$PGDATA" -w start -o "-c listen_addresses=''"; \
      psql -v ON_ERROR_STOP=1 -c "CREATE ROLE socsim LOGIN PASSWORD '$POSTGRES_PASSWORD'" -c "CREATE DATABASE socsim OWNER socsim"; \
      pg_ctl -D "$PGDATA" -w stop; \
    fi; \
    exec postgres -D "$PGDATA" -c listen_addresses='*'
