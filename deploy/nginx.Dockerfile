# nginx for deploy/docker-compose.scale.yml, from Debian 12's package, with deploy/nginx.scale.conf.
FROM debian:12-slim
RUN apt-get update && apt-get install -y --no-install-recommends nginx-light && rm -rf /var/lib/apt/lists/* \
 && rm -f /etc/nginx/sites-enabled/default
COPY deploy/nginx.scale.conf /etc/nginx/conf.d/socsim.conf
EXPOSE 8080 8181 8182 8183
CMD ["nginx", "-g", "daemon off;"]
